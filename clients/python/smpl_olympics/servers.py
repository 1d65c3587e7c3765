"""Is a server there, and does it admit what an env is about to ask of it? Servers announce
themselves every second (id, capacity, matches hosted), so an env listens for a few seconds
before its first request and raises at once, saying what to do, where it would otherwise wait
in silence: for a server that is not running, or for room a full server never has."""
import warnings

from ._client import DEFAULT_LCM_URL, MatchError, listen_for_servers

# Servers announce once a second: this is several announcements, time for a busy one.
CONNECT_TIMEOUT_S = 5.0


class NoServerError(MatchError):
    """No olympics-server announced itself on the env's LCM URL."""


class CapacityError(MatchError):
    """An env asks for more matches at once than the servers it may use admit."""


def find_servers(lcm_url="", secret_file="", server_id="", timeout_s=CONNECT_TIMEOUT_S,
                 linger_s=0.0):
    """The servers announcing on lcm_url (dicts: server_id, version, capacity, active_matches,
    sports), once server_id (any server when empty) is heard; raises NoServerError if it is
    not within timeout_s."""
    servers = listen_for_servers(lcm_url, secret_file, server_id, timeout_s, linger_s)
    if not any(server_id in ("", s["server_id"]) for s in servers):
        url = lcm_url or DEFAULT_LCM_URL
        which = f"olympics-server {server_id!r}" if server_id else "no olympics-server"
        heard = (f" (heard only: {', '.join(s['server_id'] for s in servers)})" if servers else "")
        raise NoServerError(
            f"{which} announced itself on {url} within {timeout_s:g} s{heard}. Start one with "
            f"`build/bin/olympics-server serve --lcm-url '{url}'`, or pass the lcm_url of a "
            "running one (with a secret file, only servers signing with the same secret count: "
            "docs/security.md)")
    return [s for s in servers if server_id in ("", s["server_id"])]


def check_capacity(num_matches, lcm_url="", secret_file="", server_id="",
                   timeout_s=CONNECT_TIMEOUT_S):
    """Raises CapacityError when num_matches at once is more than the servers that may host
    them admit (server_id's, or every server on the URL), NoServerError when none answers;
    warns when they admit it but host other matches already (some of these then wait)."""
    servers = find_servers(lcm_url, secret_file, server_id, timeout_s)
    if not server_id and sum(s["capacity"] for s in servers) < num_matches:
        # Any server may take a request: hear every one before counting what they admit.
        servers = find_servers(lcm_url, secret_file, server_id, timeout_s, linger_s=1.5)
    capacity = sum(s["capacity"] for s in servers)
    names = ", ".join(repr(s["server_id"]) for s in servers)
    if num_matches > capacity:
        raise CapacityError(
            f"this vector env plays {num_matches} matches at once (num_envs={num_matches}), but "
            f"server {names} admits {capacity} (its capacity); its requests beyond that would "
            f"wait for room that never comes. Start the server with --capacity {num_matches} "
            f"or more (`capacity = {num_matches}` in its config file), or use num_envs <= "
            f"{capacity}")
    free = capacity - sum(s["active_matches"] for s in servers)
    if num_matches > free:
        warnings.warn(
            f"server {names} admits {capacity} matches and hosts {capacity - free} already: "
            f"{num_matches - max(free, 0)} of this env's {num_matches} matches wait until others "
            "end", RuntimeWarning, stacklevel=3)
    return servers


def with_server_hint(error, lcm_url):
    """A client's TIMEOUT error, with what to check: the server on the URL (or its load)."""
    if not str(error).startswith("TIMEOUT:"):
        return error
    url = lcm_url or DEFAULT_LCM_URL
    return MatchError(f"{error} (is the olympics-server on {url} still running, and not stopped or "
                      f"overloaded? `build/bin/olympics-server serve --lcm-url '{url}'` starts one)")
