#include "lcmtf/nodes/static_publisher.hpp"

#include <cstdio>
#include <optional>
#include <ostream>

#include "lcmtf/nodes/static_transform_file.hpp"
#include "lcmtf/nodes/static_transform_spec.hpp"
#include "lcmtf/printable.hpp"
#include "lcmtf/programs/roll_pitch_yaw.hpp"
#include "lcmtf/static_transform_broadcaster.hpp"

namespace lcmtf::nodes {

namespace {

constexpr const char* kProgram = "lcmtf-static-publisher";

constexpr const char* kDescription =
    "Publishes static transforms (frames fixed to one another, such as a sensor on its mount) "
    "until stopped with Ctrl-C. Listeners that start later ask for them and get them at once; "
    "they are also resent every --period seconds, so a lost packet heals by itself.\n\n"
    "Give one transform with flags, or positionally as ROS users type it, or several in a "
    "YAML file. Translations are in metres, angles in radians; a rotation is either a unit "
    "quaternion (qx qy qz qw) or roll, pitch, yaw (rotation = Rz(yaw) Ry(pitch) Rx(roll)). "
    "Values left out are zero; no rotation is the identity.";

constexpr const char* kExamples =
    "Examples:\n"
    "  lcmtf-static-publisher --frame-id base_link --child-frame-id camera --x 0.1 --z 0.5 "
    "--yaw 1.5708\n"
    "  lcmtf-static-publisher 0.1 0 0.5 1.5708 0 0 base_link camera\n"
    "      (x y z yaw pitch roll frame_id child_frame_id)\n"
    "  lcmtf-static-publisher 0.1 0 0.5 0 0 0.7071068 0.7071068 base_link camera\n"
    "      (x y z qx qy qz qw frame_id child_frame_id)\n"
    "  lcmtf-static-publisher --file mounts.yaml\n\n"
    "A file holds a list of transforms with the flags' names as keys:\n"
    "  transforms:\n"
    "    - {frame_id: base_link, child_frame_id: camera, x: 0.1, z: 0.5, yaw: 1.5708}\n"
    "    - {frame_id: base_link, child_frame_id: imu, qz: 0.7071068, qw: 0.7071068}";

// The flag form: every value with the option that sets it.
struct TransformFlags {
  std::string frame_id;
  std::string child_frame_id;
  double x = 0.0, y = 0.0, z = 0.0;
  double qx = 0.0, qy = 0.0, qz = 0.0, qw = 0.0;
  double roll = 0.0, pitch = 0.0, yaw = 0.0;
  std::vector<CLI::Option*> translation_options, quaternion_options, angle_options, frame_options;

  void addTo(CLI::App& app) {
    auto number = [&app](const char* name, double& value, const char* help) {
      return app.add_option(name, value, help)
          ->check(finiteNumber())
          ->type_name("NUMBER")
          ->group("Transform flags");
    };
    frame_options = {
        app.add_option("--frame-id", frame_id, "Parent frame")
            ->type_name("FRAME")
            ->group("Transform flags"),
        app.add_option("--child-frame-id", child_frame_id, "Child frame, fixed to the parent")
            ->type_name("FRAME")
            ->group("Transform flags")};
    translation_options = {number("--x", x, "Translation along the parent's x (m)"),
                           number("--y", y, "Translation along y (m)"),
                           number("--z", z, "Translation along z (m)")};
    quaternion_options = {number("--qx", qx, "Rotation quaternion x"),
                          number("--qy", qy, "Rotation quaternion y"),
                          number("--qz", qz, "Rotation quaternion z"),
                          number("--qw", qw,
                                 "Rotation quaternion w (scalar part). Components left out are "
                                 "0 (--qz 1 alone turns half a turn about z); with none, no "
                                 "rotation")};
    angle_options = {number("--roll", roll, "Rotation about x (rad)"),
                     number("--pitch", pitch, "Rotation about y (rad)"),
                     number("--yaw", yaw, "Rotation about z (rad)")};
  }

  static bool anyGiven(const std::vector<CLI::Option*>& options) {
    for (const CLI::Option* option : options) {
      if (option->count() > 0) return true;
    }
    return false;
  }

  bool given() const {
    return anyGiven(frame_options) || anyGiven(translation_options) ||
           anyGiven(quaternion_options) || anyGiven(angle_options);
  }

  StaticTransformSpec spec() const {
    StaticTransformSpec spec;
    spec.origin = "flags";
    if (frame_options[0]->count() == 0) throw CommandLineError("--frame-id is required");
    if (frame_options[1]->count() == 0) throw CommandLineError("--child-frame-id is required");
    if (anyGiven(quaternion_options) && anyGiven(angle_options)) {
      throw CommandLineError(
          "--qx/--qy/--qz/--qw and --roll/--pitch/--yaw both given: give the rotation one way");
    }
    spec.frame_id = frame_id;
    spec.child_frame_id = child_frame_id;
    spec.translation = Eigen::Vector3d(x, y, z);
    if (anyGiven(quaternion_options)) spec.quaternion_xyzw = Eigen::Vector4d(qx, qy, qz, qw);
    if (anyGiven(angle_options)) spec.roll_pitch_yaw = RollPitchYaw{roll, pitch, yaw};
    return spec;
  }
};

StaticTransformSpec positionalSpec(const std::vector<std::string>& values) {
  StaticTransformSpec spec;
  spec.origin = "positional arguments";
  const std::size_t count = values.size();
  const auto isNumber = [](const std::string& text) { return strictNumber(text).has_value(); };
  const bool ros1_period =
      count == 10 || count == 11 || (count == 9 && !isNumber(values[6]) && isNumber(values[8]));
  if (ros1_period) {
    throw CommandLineError(
        "got " + std::to_string(count) +
        " positional arguments ending in a number: a trailing publishing period (ROS 1) is not "
        "taken here; transforms are resent every --period seconds");
  }
  if (count != 8 && count != 9) {
    throw CommandLineError("got " + std::to_string(count) +
                           " positional arguments; expected 8 (x y z yaw pitch roll frame_id "
                           "child_frame_id) or 9 (x y z qx qy qz qw frame_id child_frame_id)");
  }
  const char* names8[] = {"x", "y", "z", "yaw", "pitch", "roll"};
  const char* names9[] = {"x", "y", "z", "qx", "qy", "qz", "qw"};
  std::vector<double> numbers;
  for (std::size_t i = 0; i + 2 < count; ++i) {
    const std::string name = count == 8 ? names8[i] : names9[i];
    numbers.push_back(parseFiniteNumber(
        values[i], "positional argument " + std::to_string(i + 1) + " (" + name + ")"));
  }
  spec.translation = Eigen::Vector3d(numbers[0], numbers[1], numbers[2]);
  if (count == 8) {
    spec.roll_pitch_yaw = RollPitchYaw{numbers[5], numbers[4], numbers[3]};
  } else {
    spec.quaternion_xyzw = Eigen::Vector4d(numbers[3], numbers[4], numbers[5], numbers[6]);
  }
  spec.frame_id = values[count - 2];
  spec.child_frame_id = values[count - 1];
  return spec;
}

std::string numbers(std::initializer_list<double> values) {
  std::string text = "[";
  for (double value : values) {
    char number[32];
    std::snprintf(number, sizeof number, "%.6g", value == 0.0 ? 0.0 : value);  // never "-0"
    text += (text.size() > 1 ? " " : "") + std::string(number);
  }
  return text + "]";
}

}  // namespace

std::string describeStaticTransform(const TransformStamped& transform) {
  const Eigen::Vector3d& t = transform.transform.translation;
  const Eigen::Quaterniond& q = transform.transform.rotation;
  const RollPitchYaw angles = toRollPitchYaw(q);
  return transform.parent_frame + " -> " + transform.child_frame + ": translation " +
         numbers({t.x(), t.y(), t.z()}) + " m, rotation xyzw " +
         numbers({q.x(), q.y(), q.z(), q.w()}) + " (roll pitch yaw " +
         numbers({angles.roll, angles.pitch, angles.yaw}) + " rad)";
}

std::optional<int> parseStaticPublisherCommandLine(const std::vector<std::string>& args,
                                                   StaticPublisherOptions& options,
                                                   std::ostream& out, std::ostream& err) {
  auto app = makeToolApp(kProgram, kDescription, kExamples);
  TransformFlags flags;
  flags.addTo(*app);
  std::vector<std::string> positional;
  std::vector<std::string> files;
  double period_seconds = 1.0;
  app->add_option("pose", positional,
                  "x y z yaw pitch roll frame_id child_frame_id, or\n"
                  "x y z qx qy qz qw frame_id child_frame_id")
      ->type_name("");
  app->add_option("--file", files, "YAML file of transforms (may be given more than once)")
      ->type_name("FILE")
      ->allow_extra_args(false);  // one file each time, so that a pose after it stays positional
  app->add_option("--period", period_seconds,
                  "Seconds between resends of the whole set; 0: only at start and on request")
      ->check(finiteNumber())
      ->check(CLI::Range(0.0, 3600.0))
      ->type_name("SECONDS")
      ->capture_default_str();
  app->add_option(
         "--authority", options.authority,
         "Name the transforms are signed with (default: " + std::string(kProgram) + "@host:pid)")
      ->check(sendableName())
      ->type_name("NAME");
  app->add_flag("--check", options.check_only,
                "Check the transforms, print them and exit without publishing");
  addConnectionOptions(*app, options.connection, /*with_dynamic=*/false);
  if (auto status = parseCommandLine(*app, args, out, err)) return status;

  try {
    std::vector<StaticTransformSpec> specs;
    if (flags.given() && !positional.empty()) {
      throw CommandLineError(
          "a transform given both as flags and as positional arguments: use one form");
    }
    if (flags.given()) specs.push_back(flags.spec());
    if (!positional.empty()) specs.push_back(positionalSpec(positional));
    for (const std::string& file : files) {
      for (StaticTransformSpec& spec : loadStaticTransformFile(file)) specs.push_back(spec);
    }
    if (specs.empty()) {
      throw CommandLineError(
          "nothing to publish: give a transform with --frame-id and --child-frame-id, as "
          "positional arguments, or with --file");
    }
    options.transforms = toStaticTransforms(specs, now());
  } catch (const CommandLineError& e) {
    return reportBadArguments(*app, e.what(), err);
  }
  options.resend_period = secondsToDuration(period_seconds);
  if (options.authority.empty()) options.authority = programAuthority(kProgram);
  return std::nullopt;
}

int runStaticPublisher(const StaticPublisherOptions& options, std::ostream& out, std::ostream& err,
                       const std::atomic<bool>& stop) {
  std::unique_ptr<lcm::LCM> lcm;
  // Answering requests before saying it publishes, so that whoever waits for the line may ask.
  std::optional<StaticTransformBroadcaster> broadcaster;
  if (!options.check_only) {
    lcm = openLcmOrReport(options.connection.lcm_url, kProgram, err);
    if (!lcm) return kExitBadArguments;
    StaticBroadcasterOptions broadcaster_options;
    broadcaster_options.channel = options.connection.static_channel;
    broadcaster_options.request_channel = options.connection.request_channel;
    broadcaster_options.authority = options.authority;
    broadcaster_options.resend_period = options.resend_period;
    broadcaster.emplace(*lcm, broadcaster_options);
    if (!broadcaster->sendTransform(options.transforms)) {
      err << kProgram << ": LCM could not publish on " << options.connection.static_channel
          << " at " << describeLcmUrl(options.connection.lcm_url) << '\n';
      return kExitFailure;
    }
  }
  const std::string count = std::to_string(options.transforms.size()) + " static transform" +
                            (options.transforms.size() == 1 ? "" : "s");
  if (options.check_only) {
    out << count << ", nothing published (--check):\n";
  } else {
    out << "Publishing " << count << " on " << options.connection.static_channel << " at "
        << describeLcmUrl(options.connection.lcm_url) << " as '" << options.authority << "'";
    if (options.resend_period > Duration::zero()) {
      out << ", resent every " << toSeconds(options.resend_period) << " s";
    }
    out << ", and whenever asked on " << options.connection.request_channel << ":\n";
  }
  for (const TransformStamped& transform : options.transforms) {
    out << "  " << terminalSafe(describeStaticTransform(transform)) << '\n';
  }
  out << std::flush;
  if (options.check_only) return kExitSuccess;

  while (!stop.load()) {
    if (!handleLcmFor(*lcm, std::chrono::milliseconds(20))) {
      err << kProgram << ": LCM stopped working at " << describeLcmUrl(options.connection.lcm_url)
          << '\n';
      return kExitFailure;
    }
    broadcaster->resendIfDue();
  }
  out << "Stopped after answering " << broadcaster->requestsAnswered() << " request"
      << (broadcaster->requestsAnswered() == 1 ? "" : "s") << ".\n";
  return kExitSuccess;
}

int staticPublisherCommand(const std::vector<std::string>& args, std::ostream& out,
                           std::ostream& err, const std::atomic<bool>& stop) {
  StaticPublisherOptions options;
  if (auto status = parseStaticPublisherCommandLine(args, options, out, err)) return *status;
  return runStaticPublisher(options, out, err, stop);
}

}  // namespace lcmtf::nodes
