// lcm-spy's TF and joint tables, on messages encoded by the C++ types (write_sample_messages)
// and decoded by the Java ones: the rows they show, and that lcm-spy finds both plugins in the
// types jar as it looks for plugins.
// usage: java -cp lcm.jar:lcmtf_types.jar:CLASSES SpyTablesShowDecodedMessages MESSAGES_DIR TYPES_JAR
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import lcm.spy.SpyPlugin;
import lcm.util.ClassDiscoverer;
import lcmtf.joint_state_t;
import lcmtf.spy.JointStateTableModel;
import lcmtf.spy.TfTableModel;
import lcmtf.tf_message_t;

public final class SpyTablesShowDecodedMessages {
  private static int failures = 0;

  private static void expect(String what, Object actual, Object expected) {
    if (expected.equals(actual)) return;
    System.err.println("FAIL: " + what + ": got '" + actual + "', expected '" + expected + "'");
    ++failures;
  }

  private static void expectRow(javax.swing.table.TableModel table, int row, String... cells) {
    for (int column = 0; column < cells.length; ++column) {
      expect("row " + row + ", column '" + table.getColumnName(column) + "'",
          table.getValueAt(row, column), cells[column]);
    }
  }

  public static void main(String[] args) throws Exception {
    final tf_message_t batch =
        new tf_message_t(Files.readAllBytes(Paths.get(args[0], "tf_message_t.bin")));
    final TfTableModel tf = new TfTableModel();
    // Two seconds after the first stamp; the rotation is (0, 0, 0.6, 0.8): 73.74 deg about z.
    tf.show(batch, 1700000000000002L + 2_000_000L);
    expect("TF rows", tf.getRowCount(), 2);
    expectRow(tf, 0, "world \u2192 base_link", "1.500", "2.500", "-3.250", "0.00", "0.00",
        "73.74", "2.000");
    expectRow(tf, 1, "base_link \u2192 camera_optical", "0.125", "2.500", "-3.250", "0.00", "0.00",
        "73.74", "2.000");

    final joint_state_t joints =
        new joint_state_t(Files.readAllBytes(Paths.get(args[0], "joint_state_t.bin")));
    final JointStateTableModel table = new JointStateTableModel();
    table.show(joints);
    expect("joint rows", table.getRowCount(), 3);
    expectRow(table, 0, "shoulder_pan", "0.5000", "0.1000", "-");
    expectRow(table, 1, "elbow", "-1.2500", "0.2000", "-");
    expectRow(table, 2, "wrist_roll", "3.0000", "-0.3000", "-");

    // lcm-spy makes a plugin of every class on its CLASSPATH that implements SpyPlugin.
    final List<SpyPlugin> plugins = new ArrayList<>();
    ClassDiscoverer.findClasses(args[1], (name, raw) -> {
      final Class<?> found = raw;
      for (Class<?> implemented : found.getInterfaces()) {
        if (!implemented.equals(SpyPlugin.class)) continue;
        try {
          plugins.add((SpyPlugin) found.getConstructor().newInstance());
        } catch (ReflectiveOperationException e) {
          System.err.println("FAIL: cannot make plugin " + name + ": " + e);
          ++failures;
        }
      }
    });
    int handling_tf = 0;
    int handling_joints = 0;
    for (SpyPlugin plugin : plugins) {
      if (plugin.canHandle(tf_message_t.LCM_FINGERPRINT)) ++handling_tf;
      if (plugin.canHandle(joint_state_t.LCM_FINGERPRINT)) ++handling_joints;
    }
    expect("plugins found in the types jar", plugins.size(), 2);
    expect("plugins for tf_message_t", handling_tf, 1);
    expect("plugins for joint_state_t", handling_joints, 1);
    expect("the TF plugin's menu entry",
        plugins.stream()
            .filter(p -> p.canHandle(tf_message_t.LCM_FINGERPRINT))
            .map(p -> p.getAction(null, null).getValue(javax.swing.Action.NAME))
            .findFirst()
            .orElse(""),
        "TF table");

    if (failures > 0) System.exit(1);
    System.out.println("lcm-spy tables show the decoded messages; both plugins found");
  }
}
