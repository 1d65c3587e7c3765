"""A private olympics-server for an env (or a training run) that was given no lcm_url.

It listens on a URL of its own (a multicast group and a UDP port picked at random, the port one
the kernel says is free), so two users or two envs on one host never meet, under an id of its
own that the env addresses its requests to. It is sized for what the env asks (capacity), waits
for actions as long as a learner takes between steps (TRAINING_SERVER_FLAGS), and stops when the
env closes, when the env object is collected, when Python exits, and when the process that
started it dies however it dies (SIGKILL included: Linux's parent-death signal).
"""
import ctypes
import os
import queue
import random
import shutil
import signal
import socket
import subprocess
import tempfile
import threading
import time
import weakref

# A learner's matches stand still while it updates its policy: a private server waits for its
# actions (10 min) instead of forfeiting it after a few missed ticks.
TRAINING_SERVER_FLAGS = ["--silent-timeout-s", "600", "--action-deadline-ms", "600000",
                         "--max-missed-ticks", "100000"]
START_TIMEOUT_S = 60.0

_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def find_program(name):
    """A built program (olympics-server, olympics-agent): $OLYMPICS_<NAME>, $OLYMPICS_BIN_DIR,
    the one a wheel ships (smpl_olympics/bin), the build tree this package sits in
    (build/python/smpl_olympics -> build/bin), PATH, ./build/bin. Raises FileNotFoundError
    saying how to get one."""
    candidates = (os.environ.get("OLYMPICS_" + name.split("-")[1].upper()),
                  os.path.join(os.environ.get("OLYMPICS_BIN_DIR", ""), name),
                  os.path.join(_PACKAGE, "bin", name),
                  os.path.join(_PACKAGE, "..", "..", "bin", name),
                  shutil.which(name), os.path.join("build", "bin", name))
    for candidate in candidates:
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    raise FileNotFoundError(
        f"{name} not found: build the project (bash deploy/build.sh), put {name} on PATH or set "
        f"OLYMPICS_BIN_DIR to its folder (pip install ./clients/python ships one)")


def private_url():
    """udpm URL on a random group of 239.255/16 and a UDP port no socket holds now."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        probe.bind(("", 0))
        port = probe.getsockname()[1]
    rng = random.SystemRandom()
    group = f"239.255.{rng.randrange(256)}.{rng.randrange(1, 255)}"
    return f"udpm://{group}:{port}?ttl=0&recv_buf_size=4194304"


def _die_with(parent_pid):
    """Runs in the server before exec: Linux sends it SIGTERM when its parent dies, however it
    dies, and the server stores what it has and stops."""
    def arm():
        PR_SET_PDEATHSIG = 1
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)
        if os.getppid() != parent_pid:  # the parent died before the signal was armed
            os._exit(1)
    return arm


# The parent-death signal follows the *thread* that forked: a server started from a worker
# thread would stop when that thread ends. Servers are therefore forked from the main thread
# when that is the caller, else from one thread that lives as long as the process.
_spawns = queue.Queue()
_spawner = None
_spawner_lock = threading.Lock()


def _spawn_loop():
    while True:
        work, done = _spawns.get()
        try:
            done.put((work(), None))
        except BaseException as error:  # handed to the caller, raised there
            done.put((None, error))


def _popen_from_a_lasting_thread(*args, **kwargs):
    global _spawner
    if threading.current_thread() is threading.main_thread():
        return subprocess.Popen(*args, **kwargs)
    with _spawner_lock:
        if _spawner is None:
            _spawner = threading.Thread(target=_spawn_loop, name="olympics-server-spawner",
                                        daemon=True)
            _spawner.start()
    done = queue.Queue(maxsize=1)
    _spawns.put((lambda: subprocess.Popen(*args, **kwargs), done))
    process, error = done.get()
    if error is not None:
        raise error
    return process


def _stop(process, folder_to_remove):
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
    if folder_to_remove:
        shutil.rmtree(folder_to_remove, ignore_errors=True)


class PrivateServer:
    """olympics-server serve for one owner. folder: where its server.log and results.db go (a
    temporary folder, removed on close, when None)."""

    def __init__(self, capacity, folder=None, workers=0):
        temporary = folder is None
        self.folder = tempfile.mkdtemp(prefix="olympics-private-") if temporary else folder
        self.url = private_url()
        self.server_id = f"private_{os.getpid()}_{random.SystemRandom().getrandbits(32):08x}"
        self.capacity = int(capacity)
        self.log_path = os.path.join(self.folder, "server.log")
        command = [find_program("olympics-server"), "serve", "--lcm-url", self.url,
                   "--id", self.server_id, "--results", os.path.join(self.folder, "results.db"),
                   "--capacity", str(self.capacity), "--workers", str(int(workers)),
                   *TRAINING_SERVER_FLAGS]
        with open(self.log_path, "a") as log:
            self.process = _popen_from_a_lasting_thread(
                command, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                preexec_fn=_die_with(os.getpid()))
        # close(), garbage collection and interpreter exit all stop it (once).
        self._finalizer = weakref.finalize(self, _stop, self.process,
                                           self.folder if temporary else None)
        self._wait_started()

    @property
    def pid(self):
        return self.process.pid

    def _wait_started(self):
        give_up = time.monotonic() + START_TIMEOUT_S
        while time.monotonic() < give_up:
            with open(self.log_path) as f:
                if "olympics-server" in f.read():
                    return
            if self.process.poll() is not None:
                break
            time.sleep(0.05)
        with open(self.log_path) as f:
            tail = f.read()[-2000:]
        self.close()
        raise RuntimeError(f"the private olympics-server ({' '.join(self.process.args)}) did not "
                           f"start (exit status {self.process.returncode}); its log:\n{tail}")

    def close(self):
        self._finalizer()
