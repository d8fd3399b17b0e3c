// Opens lcm-spy's TF and joint tables as lcm-spy does (from the plugins' menu entries), on the
// sample messages, and saves what they show as PNG images. Needs a display (Xvfb in the tests).
// usage: java -cp lcm.jar:lcmtf_types.jar:CLASSES SpyTablesScreenshot MESSAGES_DIR OUT_DIR
import java.awt.Color;
import java.awt.Frame;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Paths;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import lcm.spy.ChannelData;
import lcm.spy.SpyPlugin;
import lcmtf.joint_state_t;
import lcmtf.spy.JointStateSpyPlugin;
import lcmtf.spy.TfSpyPlugin;
import lcmtf.tf_message_t;

public final class SpyTablesScreenshot {
  // Opens the plugin's window on a channel whose last message is `last`; saves it as `png`.
  private static boolean capture(SpyPlugin plugin, String channel, Object last, File png)
      throws Exception {
    final ChannelData data = new ChannelData();
    data.name = channel;
    data.last = last;
    SwingUtilities.invokeAndWait(() -> plugin.getAction(null, data).actionPerformed(null));
    Thread.sleep(1000);  // the table refreshes from the channel every 200 ms
    final BufferedImage image = new BufferedImage(760, 420, BufferedImage.TYPE_INT_RGB);
    SwingUtilities.invokeAndWait(() -> {
      for (Frame frame : Frame.getFrames()) {
        if (!(frame instanceof JFrame) || !frame.isVisible()) continue;
        if (!frame.getTitle().endsWith(": " + channel)) continue;
        final Graphics2D graphics = image.createGraphics();
        ((JFrame) frame).getContentPane().paint(graphics);
        graphics.dispose();
        frame.dispose();
      }
    });
    ImageIO.write(image, "png", png);
    // Text was drawn: the image is not of one colour.
    final int first = image.getRGB(0, 0);
    int differing = 0;
    for (int y = 0; y < image.getHeight(); y += 2) {
      for (int x = 0; x < image.getWidth(); x += 2) differing += image.getRGB(x, y) != first ? 1 : 0;
    }
    System.out.println("wrote " + png + " (" + differing + " sampled pixels not background "
        + new Color(first, true) + ")");
    return differing > 100;
  }

  public static void main(String[] args) throws Exception {
    final tf_message_t batch =
        new tf_message_t(Files.readAllBytes(Paths.get(args[0], "tf_message_t.bin")));
    final joint_state_t joints =
        new joint_state_t(Files.readAllBytes(Paths.get(args[0], "joint_state_t.bin")));
    final boolean ok = capture(new TfSpyPlugin(), "TF", batch, new File(args[1], "tf_table.png"))
        & capture(new JointStateSpyPlugin(), "JOINT_STATES", joints,
            new File(args[1], "joint_table.png"));
    System.exit(ok ? 0 : 1);
  }
}
