package lcmtf.spy;

/** Roll, pitch and yaw of a unit quaternion: rotation = Rz(yaw) Ry(pitch) Rx(roll), as ROS and URDF. */
final class RollPitchYaw {
  private RollPitchYaw() {}

  /** The three angles in degrees; pitch in [-90, 90], and yaw 0 at pitch +-90. */
  static double[] degrees(double x, double y, double z, double w) {
    final double norm = Math.sqrt(x * x + y * y + z * z + w * w);
    if (norm == 0.0 || Double.isNaN(norm) || Double.isInfinite(norm)) {
      return new double[] {Double.NaN, Double.NaN, Double.NaN};
    }
    x /= norm;
    y /= norm;
    z /= norm;
    w /= norm;
    // The rotation matrix entries the angles are read from.
    final double r00 = 1 - 2 * (y * y + z * z);
    final double r10 = 2 * (x * y + w * z);
    final double r20 = 2 * (x * z - w * y);
    final double r21 = 2 * (y * z + w * x);
    final double r22 = 1 - 2 * (x * x + y * y);
    final double r01 = 2 * (x * y - w * z);
    final double r11 = 1 - 2 * (x * x + z * z);
    final double cosPitch = Math.hypot(r00, r10);
    final double pitch = Math.atan2(-r20, cosPitch);
    double roll;
    double yaw;
    if (cosPitch > 1e-9) {
      roll = Math.atan2(r21, r22);
      yaw = Math.atan2(r10, r00);
    } else {
      roll = r20 < 0 ? Math.atan2(r01, r11) : Math.atan2(-r01, r11);
      yaw = 0.0;
    }
    return new double[] {Math.toDegrees(roll), Math.toDegrees(pitch), Math.toDegrees(yaw)};
  }
}
