package lcmtf.spy;

import java.awt.BorderLayout;
import java.awt.event.ActionEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.function.Supplier;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.JFrame;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.Timer;
import lcm.spy.ChannelData;

/** A window with a table of a channel's latest message, refreshed a few times a second. */
final class ChannelTableView {
  private static final int REFRESH_MS = 200;

  private ChannelTableView() {}

  /** The menu entry `title` of lcm-spy's channel menu, opening a window with a new table. */
  static Action action(String title, ChannelData channel, Supplier<MessageTableModel> table) {
    return new AbstractAction(title) {
      private static final long serialVersionUID = 1L;

      @Override
      public void actionPerformed(ActionEvent event) {
        open(title + ": " + channel.name, channel, table.get());
      }
    };
  }

  /** Opens the window; it shows channel.last until closed. */
  static JFrame open(String title, ChannelData channel, MessageTableModel model) {
    final JFrame frame = new JFrame(title);
    final JTable table = new JTable(model);
    table.setAutoCreateRowSorter(true);
    final int width = table.getColumnModel().getColumn(1).getPreferredWidth();
    table.getColumnModel().getColumn(0).setPreferredWidth(3 * width);  // "parent → child"
    frame.setLayout(new BorderLayout());
    frame.add(new JScrollPane(table), BorderLayout.CENTER);
    final Timer timer = new Timer(REFRESH_MS, event -> {
      final Object last = channel.last;  // set by lcm-spy's receive thread
      if (last != null) model.showMessage(last);
    });
    timer.setInitialDelay(0);
    timer.start();
    frame.addWindowListener(new WindowAdapter() {
      @Override
      public void windowClosed(WindowEvent event) {
        timer.stop();
      }
    });
    frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
    frame.setSize(760, 420);
    frame.setLocationByPlatform(true);
    frame.setVisible(true);
    return frame;
  }
}
