package lcmtf.spy;

import lcmtf.tf_message_t;
import lcmtf.transform_t;

/** A batch of transforms, one row each: parent → child, translation, roll-pitch-yaw, stamp age. */
public final class TfTableModel extends MessageTableModel {
  private static final long serialVersionUID = 1L;

  public TfTableModel() {
    super("parent \u2192 child", "x (m)", "y (m)", "z (m)", "roll (\u00b0)", "pitch (\u00b0)",
        "yaw (\u00b0)", "age (s)");
  }

  /** Shows `batch`, its stamps' ages as of `nowUtime` (microseconds since the Unix epoch). */
  public void show(tf_message_t batch, long nowUtime) {
    final transform_t[] transforms =
        batch.transforms == null ? new transform_t[0] : batch.transforms;
    final String[][] rows = new String[transforms.length][];
    for (int i = 0; i < transforms.length; ++i) rows[i] = row(transforms[i], nowUtime);
    setRows(rows);
  }

  @Override
  void showMessage(Object message) {
    show((tf_message_t) message, System.currentTimeMillis() * 1000);
  }

  private static String[] row(transform_t t, long nowUtime) {
    final double[] angles =
        RollPitchYaw.degrees(t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w);
    return new String[] {
      t.parent_frame + " \u2192 " + t.child_frame, number(t.translation.x, 3),
      number(t.translation.y, 3), number(t.translation.z, 3), number(angles[0], 2),
      number(angles[1], 2), number(angles[2], 2), number((nowUtime - t.utime) * 1e-6, 3)
    };
  }
}
