package lcmtf.spy;

import java.util.Locale;
import javax.swing.table.AbstractTableModel;

/** A table of one message's rows, as text; replaced whole by each message shown. */
abstract class MessageTableModel extends AbstractTableModel {
  private static final long serialVersionUID = 1L;

  private final String[] columns;
  private String[][] rows = new String[0][];

  MessageTableModel(String... columns) {
    this.columns = columns.clone();
  }

  /** Shows `message`, a message of the type the table is for. */
  abstract void showMessage(Object message);

  void setRows(String[][] rows) {
    this.rows = rows;
    fireTableDataChanged();
  }

  /** `value` with `digits` decimals, never "-0.000". */
  static String number(double value, int digits) {
    final String text = String.format(Locale.ROOT, "%." + digits + "f", value);
    return text.matches("-0\\.0*") ? text.substring(1) : text;
  }

  @Override
  public int getRowCount() {
    return rows.length;
  }

  @Override
  public int getColumnCount() {
    return columns.length;
  }

  @Override
  public String getColumnName(int column) {
    return columns[column];
  }

  @Override
  public Object getValueAt(int row, int column) {
    return rows[row][column];
  }
}
