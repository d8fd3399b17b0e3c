import java.io.DataInput;
import java.io.File;
import java.lang.reflect.Array;
import java.lang.reflect.InvocationTargetException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.util.LinkedHashMap;
import java.util.Map;
import lcm.lcm.LCMDataInputStream;
import lcm.spy.LCMTypeDatabase;

/**
 * Decodes each DIR/<type>.bin written by write_sample_messages the way lcm-spy decodes a channel:
 * class looked up by fingerprint in an LCMTypeDatabase (types found through CLASSPATH), then
 * built from the bytes through its DataInput constructor. Checks the class name and known fields.
 */
public class SpyDecodesLcmtf {
  private static final Map<String, Object[]> EXPECTED = new LinkedHashMap<>();

  static {
    EXPECTED.put("tf_message_t", new Object[] {
        "utime", 1700000000000001L,
        "authority", "spy_sample@host:42",
        "sequence", 17L,
        "num_transforms", 2,
        "transforms[0].child_frame", "base_link",
        "transforms[1].parent_frame", "base_link",
        "transforms[1].child_frame", "camera_optical",
        "transforms[1].translation.x", 0.125,
        "transforms[1].rotation.w", 0.8});
    EXPECTED.put("transform_t", new Object[] {
        "utime", 1700000000000004L,
        "parent_frame", "map",
        "child_frame", "odom",
        "translation.x", -7.75,
        "rotation.z", 0.6});
    EXPECTED.put("joint_state_t", new Object[] {
        "utime", 1700000000000005L,
        "authority", "spy_sample@host:44",
        "sequence", 18L,
        "num_joints", 3,
        "name[0]", "shoulder_pan",
        "name[2]", "wrist_roll",
        "position[1]", -1.25,
        "num_velocities", 3,
        "velocity[2]", -0.3,
        "num_efforts", 0});
    EXPECTED.put("resend_request_t", new Object[] {
        "utime", 1700000000000006L,
        "requester", "spy_sample_requester"});
    EXPECTED.put("robot_description_t", new Object[] {
        "utime", 1700000000000007L,
        "authority", "spy_sample@host:43",
        "robot_name", "spy_bot",
        "urdf", "<robot name=\"spy_bot\"><link name=\"base_link\"/></robot>"});
  }

  public static void main(String[] args) throws Exception {
    if (args.length != 1) {
      System.err.println("usage: SpyDecodesLcmtf DIR");
      System.exit(2);
    }
    File dir = new File(args[0]);
    LCMTypeDatabase types = new LCMTypeDatabase();
    int failures = 0;
    for (Map.Entry<String, Object[]> entry : EXPECTED.entrySet()) {
      String type = entry.getKey();
      try {
        check(types, new File(dir, type + ".bin"), type, entry.getValue());
        System.out.println("ok   lcmtf." + type);
      } catch (Exception e) {
        Throwable cause = e instanceof InvocationTargetException ? e.getCause() : e;
        System.out.println("FAIL lcmtf." + type + ": " + cause);
        failures++;
      }
    }
    File[] unexpected = dir.listFiles((d, name) ->
        name.endsWith(".bin") && !EXPECTED.containsKey(name.substring(0, name.length() - 4)));
    for (File f : unexpected == null ? new File[0] : unexpected) {
      System.out.println("FAIL " + f.getName() + ": no expected values for this type");
      failures++;
    }
    if (failures > 0) {
      System.err.println(failures + " failure(s): lcm-spy would not decode every lcmtf type with"
          + " CLASSPATH=" + System.getenv("CLASSPATH"));
      System.exit(1);
    }
  }

  private static void check(LCMTypeDatabase types, File file, String type, Object[] expected)
      throws Exception {
    if (!file.isFile()) {
      throw new Exception("missing " + file);
    }
    byte[] bytes = Files.readAllBytes(file.toPath());
    if (bytes.length < 8) {
      throw new Exception(file + " is shorter than a fingerprint");
    }
    long fingerprint = ByteBuffer.wrap(bytes, 0, 8).getLong();
    Class<?> cls = types.getClassByFingerprint(fingerprint);
    if (cls == null) {
      throw new Exception(String.format("no class for fingerprint 0x%016x", fingerprint));
    }
    if (!cls.getName().equals("lcmtf." + type)) {
      throw new Exception("fingerprint maps to " + cls.getName());
    }
    Object msg = cls.getConstructor(DataInput.class).newInstance(new LCMDataInputStream(bytes));
    for (int i = 0; i < expected.length; i += 2) {
      String path = (String) expected[i];
      Object actual = value(msg, path);
      if (!expected[i + 1].equals(actual)) {
        throw new Exception(path + " is " + actual + ", expected " + expected[i + 1]);
      }
    }
  }

  /** The value at a path such as "transforms[1].translation.x". */
  private static Object value(Object obj, String path) throws Exception {
    for (String part : path.split("\\.")) {
      int bracket = part.indexOf('[');
      String name = bracket < 0 ? part : part.substring(0, bracket);
      obj = obj.getClass().getField(name).get(obj);
      if (bracket >= 0) {
        obj = Array.get(obj, Integer.parseInt(part.substring(bracket + 1, part.length() - 1)));
      }
    }
    return obj;
  }
}
