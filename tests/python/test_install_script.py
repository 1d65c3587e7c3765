"""clients/python/install.sh picks the Python the build compiled the package for, whatever python3
is first on PATH, says which, and refuses a Python without numpy with a message instead of a
traceback (it used to run the first python3 on PATH)."""
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(REPO, "clients", "python", "install.sh")


class InstallScript(unittest.TestCase):
    def setUp(self):
        self.home = tempfile.mkdtemp(prefix="olympics-install-")
        # A python3 first on PATH that is not the build's (as pyenv's or conda's would be).
        self.bin = os.path.join(self.home, "bin")
        os.makedirs(self.bin)
        with open(os.path.join(self.bin, "python3"), "w") as f:
            f.write("#!/bin/sh\necho 'not the python the build used' >&2\nexit 3\n")
        os.chmod(os.path.join(self.bin, "python3"), 0o755)
        # The .pth goes into this user site, not the tester's.
        self.env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHON")}
        self.env.update(PATH=f"{self.bin}:{os.environ['PATH']}", HOME=self.home,
                        PYTHONUSERBASE=os.path.join(self.home, ".local"))

    def run_script(self, **extra):
        return subprocess.run(["bash", SCRIPT], env={**self.env, **extra}, capture_output=True,
                              text=True, timeout=120)

    def test_uses_the_builds_python_not_the_first_on_path(self):
        done = self.run_script()
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn(f"installing smpl_olympics for {sys.executable}", done.stdout)
        self.assertIn(f"smpl_olympics ready for {sys.executable}", done.stdout)

    def test_a_python_without_numpy_is_refused_with_what_to_do(self):
        venv = os.path.join(self.home, "bare")
        subprocess.run([sys.executable, "-m", "venv", "--without-pip", venv], check=True)
        done = self.run_script(PYTHON=os.path.join(venv, "bin", "python"))
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("has no numpy", done.stderr)
        self.assertIn("PYTHON=", done.stderr)
        self.assertNotIn("Traceback", done.stderr)


if __name__ == "__main__":
    unittest.main()
