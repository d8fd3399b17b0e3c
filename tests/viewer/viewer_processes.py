"""Starts lcmtf's programs for the viewer's tests and benchmark, and always ends them."""
import os
import re
import shutil
import signal
import subprocess
import tempfile
import time


def add_test_arguments(parser):
    """The arguments ctest gives every viewer test script."""
    parser.add_argument("--bin-dir", required=True, help="folder of lcmtf's programs")
    parser.add_argument("--source-dir", required=True, help="lcmtf's source tree")
    parser.add_argument("--shared-urdf", required=True, help="folder of the shared robot files")
    parser.add_argument("--lcm-port", type=int, required=True, help="udpm port of this test's own")


def lcm_url(port):
    """A udpm URL that stays on this machine, on a port of the caller's own."""
    return f"udpm://239.255.76.67:{port}?ttl=0"


class Programs:
    """The processes one test started; use as a context manager so that they always end."""

    def __init__(self, bin_dir):
        self.bin_dir = bin_dir
        self.running = []
        self.log_dir = tempfile.mkdtemp(prefix="lcmtf-viewer-test-")
        self.keep_logs = False  # set on failure: the folder stays for a look

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.stop_all()
        if self.keep_logs or exc[0] is not None:
            print(f"logs kept in {self.log_dir}")
        else:
            shutil.rmtree(self.log_dir, ignore_errors=True)
        return False

    def start(self, program, *args):
        """Starts bin_dir/program with args; its output goes to a log file (see log())."""
        path = os.path.join(self.bin_dir, program)
        log_path = os.path.join(self.log_dir, f"{program}-{len(self.running)}.log")
        log = open(log_path, "wb")
        process = subprocess.Popen([path, *args], stdout=log, stderr=subprocess.STDOUT,
                                   start_new_session=True)
        process.log_path = log_path
        process.log_file = log
        process.name = program
        self.running.append(process)
        return process

    def start_viewer(self, lcm_port, *args, port=0, timeout=20):
        """Starts lcmtf-viewer on `port` (0: a free one); returns (process, base URL)."""
        process = self.start("lcmtf-viewer", "--port", str(port), "--lcm-url", lcm_url(lcm_port),
                             *args)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            match = re.search(r"http://127\.0\.0\.1:(\d+)/", self.log(process))
            if match:
                return process, f"http://127.0.0.1:{match.group(1)}"
            if process.poll() is not None:
                break
            time.sleep(0.05)
        raise RuntimeError(f"lcmtf-viewer did not say its URL: {self.log(process)}")

    @staticmethod
    def log(process):
        process.log_file.flush()
        with open(process.log_path, "rb") as file:
            return file.read().decode(errors="replace")

    def stop(self, process):
        """Ends one process (its whole process group): SIGTERM, then SIGKILL after 5 s."""
        if process.poll() is None:
            try:
                os.killpg(process.pid, signal.SIGTERM)
                process.wait(timeout=5)
            except ProcessLookupError:
                pass
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
        process.log_file.close()

    def stop_all(self):
        for process in reversed(self.running):
            try:
                self.stop(process)
            except Exception as error:  # pylint: disable=broad-except
                print(f"could not stop {process.name} ({process.pid}): {error}")
        self.running = []

    def check_alive(self):
        """Raises if any started program has exited, with its output."""
        for process in self.running:
            if process.poll() is not None:
                raise RuntimeError(f"{process.name} exited with {process.returncode}:\n"
                                   f"{self.log(process)[-3000:]}")
