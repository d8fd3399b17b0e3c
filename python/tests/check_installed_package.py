"""Imports lcmtf as cmake --install laid it out and uses it once (run by ctest, isolated from
the build tree).

usage: check_installed_package.py SITE_DIR LIB_DIR
"""

import pathlib
import sys

site_dir, lib_dir = (pathlib.Path(argument).resolve() for argument in sys.argv[1:3])
sys.path.insert(0, str(site_dir))

import lcmtf  # noqa: E402  (the path above first)

assert pathlib.Path(lcmtf.__file__).resolve().parent == site_dir / "lcmtf", lcmtf.__file__
loaded = {line.split()[-1] for line in open("/proc/self/maps") if "liblcmtf" in line}
assert loaded and all(pathlib.Path(path).parent == lib_dir for path in loaded), loaded

buffer = lcmtf.Buffer()
buffer.set_transform(lcmtf.TransformStamped("a", "b", 0.0, [1, 2, 3]), "check", is_static=True)
assert buffer.lookup_transform("a", "b").translation.tolist() == [1, 2, 3]
assert lcmtf.tf_message_t.decode(lcmtf.tf_message_t().encode()).transforms == []
print(f"lcmtf imported from {site_dir} with liblcmtf from {lib_dir}")
