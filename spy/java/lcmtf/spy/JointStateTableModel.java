package lcmtf.spy;

import lcmtf.joint_state_t;

/** A joint state, one row a joint: name, position, and velocity and effort where given. */
public final class JointStateTableModel extends MessageTableModel {
  private static final long serialVersionUID = 1L;

  public JointStateTableModel() {
    super("joint", "position", "velocity", "effort");
  }

  /** Shows `state`; a velocity or effort it leaves out shows as "-". */
  public void show(joint_state_t state) {
    final int count = state.name == null ? 0 : state.name.length;
    final String[][] rows = new String[count][];
    for (int i = 0; i < count; ++i) {
      rows[i] = new String[] {
        state.name[i], valueAt(state.position, i), valueAt(state.velocity, i),
        valueAt(state.effort, i)
      };
    }
    setRows(rows);
  }

  @Override
  void showMessage(Object message) {
    show((joint_state_t) message);
  }

  private static String valueAt(double[] values, int i) {
    return values != null && i < values.length ? number(values[i], 4) : "-";
  }
}
