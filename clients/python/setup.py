"""pip install ./clients/python: the smpl_olympics package built for the Python that runs pip.

The extension (the C++ client over LCM, smpl_olympics._client) is compiled from this repository's
sources against the system's LCM, OpenSSL and pybind11 headers (Debian: liblcm-dev libssl-dev
pybind11-dev); the lcm-gen'd message types (`import olympics`) and the sports catalog
(sports.json, from `olympics-server describe --json`) are generated into the package. No network
is needed with `pip install --no-build-isolation ./clients/python`.

The catalog needs a built olympics-server: $OLYMPICS_SERVER, else olympics-server on PATH, else
build/bin/olympics-server of this repository (bash deploy/build.sh). The scripted players link the
build's sports libraries ($OLYMPICS_BUILD_DIR, else build/ of this repository) and ODE, tinyxml2
and xxHash (Debian: libode-dev libtinyxml2-dev libxxhash-dev).
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
LCM_FILES = sorted(glob.glob(os.path.join(ROOT, "lcmtypes", "*.lcm")))


def pkg_config(*args):
    try:
        return subprocess.run(["pkg-config", *args, "lcm"], check=True, capture_output=True,
                              text=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        sys.exit("pkg-config could not find LCM: install liblcm-dev and libglib2.0-dev")


def pybind11_include():
    try:
        import pybind11
        return pybind11.get_include()
    except ImportError:  # Debian's pybind11-dev puts the headers beside the system's
        if os.path.exists("/usr/include/pybind11/pybind11.h"):
            return "/usr/include"
        sys.exit("pybind11 headers not found: install pybind11-dev (or pybind11 in this Python)")


def olympics_server():
    for candidate in (os.environ.get("OLYMPICS_SERVER"), shutil.which("olympics-server"),
                      os.path.join(ROOT, "build", "bin", "olympics-server")):
        if candidate and os.access(candidate, os.X_OK):
            return candidate
    sys.exit("olympics-server not found for the sports catalog: build the project first "
             "(bash deploy/build.sh) or set OLYMPICS_SERVER")


def sports_libraries():
    build = os.environ.get("OLYMPICS_BUILD_DIR", os.path.join(ROOT, "build"))
    found = [os.path.join(build, "sports", "libolympics_sports.a"),
             os.path.join(build, "sports", "core", "libolympics_core.a")]
    missing = [f for f in found if not os.path.exists(f)]
    if missing:
        sys.exit(f"{missing[0]} not found: build the project first (bash deploy/build.sh) or set "
                 "OLYMPICS_BUILD_DIR to its build folder")
    return found


class BuildExt(build_ext):
    """lcm-gen's C++ headers and the wire schema first, then the extension."""

    def build_extensions(self):
        generated = os.path.join(os.path.abspath(self.build_temp), "lcmtypes")
        os.makedirs(generated, exist_ok=True)
        subprocess.run(["lcm-gen", "-x", "--cpp-hpath", generated, *LCM_FILES], check=True)
        subprocess.run([sys.executable, os.path.join(ROOT, "lcmtypes", "generate_wire_schema.py"),
                        os.path.join(generated, "olympics", "wire_schema.hpp"), *LCM_FILES],
                       check=True)
        for ext in self.extensions:
            ext.include_dirs.insert(0, generated)
        super().build_extensions()


class BuildPy(build_py):
    """The message types (package `olympics`) and the sports catalog beside the sources."""

    def run(self):
        super().run()
        subprocess.run(["lcm-gen", "-p", "--ppath", self.build_lib, *LCM_FILES], check=True)
        subprocess.run([olympics_server(), "describe", "--json", "--output",
                        os.path.join(self.build_lib, "smpl_olympics", "sports.json")], check=True)


cflags = pkg_config("--cflags")
libs = pkg_config("--libs")
sources = ([os.path.join(HERE, f) for f in ("bindings.cpp", "vector_bindings.cpp",
                                           "policy_bindings.cpp", "server_bindings.cpp")] +
           sorted(glob.glob(os.path.join(ROOT, "clients", "cpp", "*.cpp"))) +
           # the policies olympics-agent plays (NativePolicy), without its programs' mains and
           # the agent's --calls log (which reads the sports registry)
           sorted(f for f in glob.glob(os.path.join(ROOT, "clients", "agent", "*.cpp"))
                  if os.path.basename(f) not in ("main.cpp", "snapshot_tool.cpp",
                                                 "play_match.cpp", "call_log.cpp")) +
           # the scripted players' control toolkit (docs/control.md)
           sorted(glob.glob(os.path.join(ROOT, "clients", "agent", "control", "*.cpp"))) +
           sorted(glob.glob(os.path.join(ROOT, "protocol", "*.cpp"))))
extension = Extension(
    "smpl_olympics._client",
    sources=sources,  # absolute: objects then stay under build/
    # sports/core: self_observation_layout.h alone (header-only), which the policies read by
    include_dirs=[os.path.join(ROOT, d) for d in ("lcmtypes", "protocol", "clients/cpp",
                                                  "clients/agent", "clients/python",
                                                  "sports/core", "sports")] +
                 [pybind11_include(), "/usr/include/eigen3"],
    extra_compile_args=["-std=c++20", "-O2", "-fvisibility=hidden",
                        *[f for f in cflags if not f.startswith("-I")]],
    # The control toolkit models the player's body and ball with the server's own code: linked
    # from the CMake build's static libraries (position-independent), not compiled again.
    extra_link_args=sports_libraries() + libs + ["-lcrypto", "-lode", "-ltinyxml2", "-lxxhash"],
    language="c++",
)
extension.include_dirs += [f[2:] for f in cflags if f.startswith("-I")]

setup(
    name="smpl_olympics",
    version="0.1.0",
    description="Python client of the SMPL Olympics humanoid sports match server",
    python_requires=">=3.9",
    packages=["smpl_olympics"],
    install_requires=["numpy"],
    ext_modules=[extension],
    cmdclass={"build_ext": BuildExt, "build_py": BuildPy},
    zip_safe=False,
)
