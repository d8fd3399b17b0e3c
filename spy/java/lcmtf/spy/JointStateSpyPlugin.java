package lcmtf.spy;

import javax.swing.Action;
import javax.swing.JDesktopPane;
import lcm.spy.ChannelData;
import lcm.spy.SpyPlugin;
import lcmtf.joint_state_t;

/** lcm-spy's "Joint table" for a channel of joint_state_t: a row per joint. */
public final class JointStateSpyPlugin implements SpyPlugin {
  @Override
  public boolean canHandle(long fingerprint) {
    return fingerprint == joint_state_t.LCM_FINGERPRINT;
  }

  @Override
  public Action getAction(JDesktopPane desktop, ChannelData channel) {
    return ChannelTableView.action("Joint table", channel, JointStateTableModel::new);
  }
}
