"""`pip wheel ./clients/python` with build isolation (the pinned build requirements come from the
package index) builds the wheel with the project's CMake; the wheel installs into a fresh venv
without the system's packages (numpy from the index) and plays a match on the olympics-server it
carries, with nothing else started and nothing of the build on PATH.

The wheel's CMake build folder is kept beside the test's build folder (build/ -> build-pip-wheel/),
so a rerun recompiles only what changed. With ccache installed (deploy/build.sh uses it too) and
its base directory at the checkout, a first wheel build after deploy/build.sh is cache hits for
everything but the module: both builds are Ninja builds one folder below the checkout, so their
compile commands, made relative by ccache, are the same."""
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest

from server_process import BIN

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# BIN is the build's bin/ folder: the wheel's build folder goes beside the build folder.
BUILD_DIR = os.path.dirname(os.path.abspath(BIN)) + "-pip-wheel"

PLAY = textwrap.dedent("""
    import json, os
    import numpy as np
    import olympics                       # the lcm-gen'd message types come with the package
    import smpl_olympics
    from smpl_olympics import OlympicsParallelEnv
    env = OlympicsParallelEnv(sport="sandbox", mode="1v1", time_limit_s=1.0)  # no lcm_url
    env.reset(seed=3)
    while env.agents:
        env.step({a: np.zeros(69, np.float32) for a in env.agents})
    print(json.dumps({"package": smpl_olympics.__file__, "types": olympics.match_result_t.__name__,
                      "server": env._server.process.args[0], "ticks": env.result["ticks"],
                      "assets": os.environ["OLYMPICS_ASSET_DIR"]}))
    env.close()
""")


def clean_environment():
    """Nothing of the test's build: no PYTHONPATH, no OLYMPICS_* paths, no build/bin on PATH."""
    env = {k: v for k, v in os.environ.items()
           if k != "PYTHONPATH" and not k.startswith("OLYMPICS_")}
    if shutil.which("ccache") and "CMAKE_CXX_COMPILER_LAUNCHER" not in env:
        env["CMAKE_CXX_COMPILER_LAUNCHER"] = "ccache"
        env["CMAKE_C_COMPILER_LAUNCHER"] = "ccache"
        env.setdefault("CCACHE_BASEDIR", REPO)
        # The compiler the test's build used, by the same name: scikit-build-core otherwise takes
        # Python's (x86_64-linux-gnu-g++), and ccache counts the name, so nothing would hit.
        for lang, var in (("CXX", "CXX"), ("C", "CC")):
            compiler = build_cache_entry(f"CMAKE_{lang}_COMPILER")
            if compiler and var not in env:
                env[var] = compiler
    return env


def build_cache_entry(name):
    """A CMake cache entry of the test's own build folder (the one BIN belongs to), or None."""
    try:
        with open(os.path.join(os.path.dirname(os.path.abspath(BIN)), "CMakeCache.txt")) as f:
            for line in f:
                if line.startswith(name + ":"):
                    return line.split("=", 1)[1].strip()
    except OSError:
        pass
    return None


class PipInstall(unittest.TestCase):
    def test_wheel_with_build_isolation_installs_into_a_fresh_venv_and_plays(self):
        folder = tempfile.mkdtemp(prefix="olympics-venv-")
        env = clean_environment()
        builder = os.path.join(folder, "builder")
        subprocess.run([sys.executable, "-m", "venv", builder], check=True)
        wheels = os.path.join(folder, "wheels")
        build = subprocess.run(
            [os.path.join(builder, "bin", "python"), "-m", "pip", "wheel", "--no-deps", "-v",
             "-w", wheels, f"--config-settings=build-dir={BUILD_DIR}",
             os.path.join(REPO, "clients", "python")],
            env=env, capture_output=True, text=True, cwd=folder)
        self.assertEqual(build.returncode, 0, build.stdout[-4000:] + build.stderr[-3000:])
        (wheel,) = glob.glob(os.path.join(wheels, "smpl_olympics-*.whl"))

        # The project's own CMake built it, in the kept folder, with the package-only option.
        with open(os.path.join(BUILD_DIR, "CMakeCache.txt")) as f:
            cache = f.read()
        self.assertIn(f"CMAKE_HOME_DIRECTORY:INTERNAL={REPO}\n", cache)
        self.assertIn("OLYMPICS_PYTHON_PACKAGE_ONLY:BOOL=ON", cache)
        # Ninja tracks headers: a header change recompiles what includes it.
        deps = subprocess.run(["ninja", "-C", BUILD_DIR, "-t", "deps",
                               "clients/CMakeFiles/smpl_olympics_client.dir/python/bindings.cpp.o"],
                              capture_output=True, text=True)
        # (ccache's base directory makes the compiler's paths, and so Ninja's, relative to it)
        headers = {os.path.normpath(os.path.join(BUILD_DIR, line.strip()))
                   for line in deps.stdout.splitlines()[1:] if line.strip()}
        self.assertIn(os.path.join(REPO, "clients", "python", "bindings.h"), headers,
                      deps.stdout[-2000:] + deps.stderr[-2000:])

        venv = os.path.join(folder, "venv")
        subprocess.run([sys.executable, "-m", "venv", venv], check=True)  # no system packages
        python = os.path.join(venv, "bin", "python")
        install = subprocess.run([python, "-m", "pip", "install", wheel], env=env,
                                 capture_output=True, text=True, cwd=folder)
        self.assertEqual(install.returncode, 0, install.stdout[-3000:] + install.stderr[-3000:])
        played = subprocess.run([python, "-c", PLAY], env=env, capture_output=True, text=True,
                                cwd=folder, timeout=300)
        self.assertEqual(played.returncode, 0, played.stderr[-3000:])
        out = json.loads(played.stdout.strip().splitlines()[-1])
        self.assertTrue(out["package"].startswith(venv), out["package"])
        self.assertTrue(out["server"].startswith(venv), f"server not the wheel's: {out['server']}")
        self.assertTrue(out["assets"].startswith(venv), out["assets"])
        self.assertEqual(out["types"], "match_result_t")
        self.assertGreater(out["ticks"], 0)
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
