package lcmtf.spy;

import javax.swing.Action;
import javax.swing.JDesktopPane;
import lcm.spy.ChannelData;
import lcm.spy.SpyPlugin;
import lcmtf.tf_message_t;

/** lcm-spy's "TF table" for a channel of tf_message_t: a row per transform. */
public final class TfSpyPlugin implements SpyPlugin {
  @Override
  public boolean canHandle(long fingerprint) {
    return fingerprint == tf_message_t.LCM_FINGERPRINT;
  }

  @Override
  public Action getAction(JDesktopPane desktop, ChannelData channel) {
    return ChannelTableView.action("TF table", channel, TfTableModel::new);
  }
}
