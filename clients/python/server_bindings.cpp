// smpl_olympics._client.listen_for_servers: the servers that announce themselves on an LCM URL
// (each does every second on OLY_ANNOUNCE), so that an env can say at once that no server is
// there, or that one admits fewer matches than it is about to ask for, instead of waiting.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <string>

#include "auth.h"
#include "bindings.h"
#include "channels.h"
#include "olympics/server_announce_t.hpp"
#include "transport.h"

namespace py = pybind11;

namespace olympics::python {
namespace {

using Clock = std::chrono::steady_clock;

// Listens until `server_id` (any server when empty) has announced itself, then `linger_s` more
// for the others, or until `timeout_s` passed: the servers heard, by id.
std::map<std::string, olympics::server_announce_t> listen(const std::string& lcm_url,
                                                          const std::string& secret_file,
                                                          const std::string& server_id,
                                                          double timeout_s, double linger_s) {
  protocol::Transport transport(
      protocol::TransportOptions(lcm_url, 0.0, 1, protocol::load_secret(secret_file)));
  std::map<std::string, olympics::server_announce_t> heard;
  std::optional<Clock::time_point> found;
  transport.subscribe_to<olympics::server_announce_t>(
      protocol::kAnnounce, [&](const std::string&, const olympics::server_announce_t& a) {
        heard[a.server_id] = a;
        if (!found && (server_id.empty() || a.server_id == server_id)) found = Clock::now();
      });
  const auto seconds = [](double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  };
  const auto give_up = Clock::now() + seconds(timeout_s);
  while (true) {
    const auto until = found ? std::min(give_up, *found + seconds(linger_s)) : give_up;
    if (Clock::now() >= until) break;
    transport.handle(50);
  }
  return heard;
}

}  // namespace

void bind_server_listener(py::module_& m) {
  m.attr("DEFAULT_LCM_URL") = protocol::kDefaultLcmUrl;
  m.def(
      "listen_for_servers",
      [](const std::string& lcm_url, const std::string& secret_file, const std::string& server_id,
         double timeout_s, double linger_s) {
        std::map<std::string, olympics::server_announce_t> heard;
        {
          py::gil_scoped_release release;
          heard = listen(lcm_url, secret_file, server_id, timeout_s, linger_s);
        }
        py::list servers;
        for (const auto& [id, a] : heard) {
          py::dict d;
          d["server_id"] = id;
          d["version"] = a.server_version;
          d["capacity"] = a.capacity;
          d["active_matches"] = a.active_matches;
          d["sports"] = a.sports;
          servers.append(d);
        }
        return servers;
      },
      py::arg("lcm_url") = "", py::arg("secret_file") = "", py::arg("server_id") = "",
      py::arg("timeout_s") = 5.0, py::arg("linger_s") = 0.0,
      "the servers heard announcing on lcm_url (dicts: server_id, version, capacity, "
      "active_matches, sports): listens until server_id (any when empty) is heard, then "
      "linger_s more, or until timeout_s");
}

}  // namespace olympics::python
