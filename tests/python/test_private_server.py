"""An env given no lcm_url starts a private olympics-server for itself (real processes): it plays
with nothing else started, is sized for the envs asked, does not meet another user's, and leaves
no server behind: not after close(), not after its process is killed with SIGKILL, and it does
not stop early when the thread that created the env ends."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
import unittest

import numpy as np

from smpl_olympics import OlympicsParallelEnv, OlympicsVectorEnv
from smpl_olympics.servers import find_servers

HERE = os.path.dirname(os.path.abspath(__file__))


def alive(pid):
    """A process that exists and is not a zombie waiting for its reaper."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def wait_gone(pid, timeout_s=30.0):
    give_up = time.monotonic() + timeout_s
    while alive(pid) and time.monotonic() < give_up:
        time.sleep(0.05)
    return not alive(pid)


def play_to_end(env):
    while env.agents:
        env.step({a: np.zeros(env.action_size(), np.float32) for a in env.agents})
    return env.result


class PrivateServer(unittest.TestCase):
    def test_parallel_env_plays_on_its_own_server_and_stops_it_on_close(self):
        env = OlympicsParallelEnv(sport="sandbox", mode="1v1", time_limit_s=0.5)
        self.assertEqual(env.lcm_url, "")  # nothing started before the first reset
        env.reset(seed=3)
        server = env._server
        self.assertTrue(alive(server.pid))
        self.assertGreater(play_to_end(env)["ticks"], 0)
        env.reset(seed=4)  # the next match on the same server
        self.assertIs(env._server, server)
        play_to_end(env)
        env.close()
        self.assertFalse(alive(server.pid), "the private server outlived close()")
        self.assertFalse(os.path.exists(server.folder), "its temporary folder stayed")

    def test_vector_env_server_is_sized_for_its_envs_and_private(self):
        # 70 > the 64 a server admits by default: the private one admits what is asked.
        big = OlympicsVectorEnv(70, sport="sandbox", mode="solo", seed=1, time_limit_s=0.5)
        small = OlympicsVectorEnv(2, sport="sandbox", mode="1v1", seed=1, time_limit_s=0.5)
        try:
            big._check_servers()  # starts it, listens to its announcement: no match played
            small.reset()
            heard = find_servers(lcm_url=big.lcm_url, linger_s=1.5)
            self.assertEqual([(s["server_id"], s["capacity"]) for s in heard],
                             [(big._server.server_id, 70)], "one server on the URL, sized 70")
            self.assertNotEqual(big.lcm_url, small.lcm_url)
            for _ in range(3):
                obs, *_ = small.step(np.zeros((2, 2, small.action_size), np.float32))
            self.assertEqual(obs.shape[:2], (2, 2))
        finally:
            pids = [e._server.pid for e in (big, small)]
            big.close()
            small.close()
        self.assertFalse(any(alive(p) for p in pids))

    def test_env_created_in_a_thread_keeps_its_server_after_the_thread_ends(self):
        # Linux's parent-death signal follows the thread that forked: a server forked by this
        # worker thread would be stopped when the thread ends.
        made = {}

        def make():
            made["env"] = OlympicsParallelEnv(sport="sandbox", mode="solo", time_limit_s=0.5)
            made["env"].reset(seed=1)

        worker = threading.Thread(target=make)
        worker.start()
        worker.join()
        env = made["env"]
        time.sleep(0.5)
        self.assertTrue(alive(env._server.pid), "the server stopped with the thread")
        self.assertGreater(play_to_end(env)["ticks"], 0)
        env.close()

    def test_no_server_left_when_the_process_is_killed(self):
        script = textwrap.dedent("""
            import sys, time
            from smpl_olympics import OlympicsParallelEnv, OlympicsVectorEnv
            env = OlympicsParallelEnv(sport="sandbox", mode="solo", time_limit_s=60)
            env.reset(seed=1)
            vec = OlympicsVectorEnv(2, sport="sandbox", mode="solo", seed=1, time_limit_s=60)
            vec.reset()
            print(env._server.pid, vec._server.pid, flush=True)
            time.sleep(600)
        """)
        child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                                 text=True, cwd=HERE)
        try:
            pids = [int(p) for p in child.stdout.readline().split()]
            self.assertEqual(len(pids), 2, "the child did not start its envs")
            self.assertTrue(all(alive(p) for p in pids))
            child.send_signal(signal.SIGKILL)
            child.wait()
            for pid in pids:
                self.assertTrue(wait_gone(pid), f"server {pid} outlived its SIGKILLed parent")
        finally:
            child.kill()
            child.wait()

    def test_connecting_to_a_deployment_stays_one_argument(self):
        # lcm_url given: no server is started, the env talks to that URL (none there: it says so).
        env = OlympicsParallelEnv(sport="sandbox", mode="solo", connect_timeout_s=0.5,
                                  lcm_url="udpm://239.255.76.67:7000?ttl=0")
        with self.assertRaisesRegex(Exception, "7000"):
            env.reset(seed=1)
        self.assertIsNone(env._server)

    def test_joining_without_a_url_is_refused(self):
        with self.assertRaisesRegex(ValueError, "lcm_url"):
            OlympicsParallelEnv(sport="sandbox", mode="1v1", learner="me")
        with self.assertRaisesRegex(ValueError, "lcm_url"):
            OlympicsVectorEnv(2, sport="sandbox", mode="1v1", learner="me")


if __name__ == "__main__":
    unittest.main()
