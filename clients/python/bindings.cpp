// Python bindings over the C++ client (module smpl_olympics._client). Blocking calls release the
// GIL; observations arrive as float32 numpy arrays of shape (slots, obs_size).
#include "bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "match_client.h"

namespace py = pybind11;
using namespace olympics::client;

namespace {

py::array_t<float> rows_to_array(const std::vector<std::vector<float>>& rows) {
  const size_t cols = rows.empty() ? 0 : rows[0].size();
  py::array_t<float> out({rows.size(), cols});
  auto view = out.mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t k = 0; k < cols; ++k) view(i, k) = rows[i][k];
  return out;
}

py::dict describe(const olympics::match_created_t& m) {
  py::dict d;
  d["match_id"] = m.match_id;
  d["server_id"] = m.server_id;
  d["sport"] = m.sport;
  d["mode"] = m.mode;
  d["seed"] = m.seed;
  d["realtime"] = m.realtime;
  d["num_slots"] = m.num_slots;
  d["slot_team"] = m.slot_team;
  d["obs_size"] = m.obs_size;
  d["action_size"] = m.action_size;
  d["control_hz"] = m.control_hz;
  d["time_limit_s"] = m.time_limit_s;
  d["options"] = m.options;
  py::list blocks;  // (name, size) in order: where each named block of an observation lies
  for (int i = 0; i < m.num_obs_blocks; ++i)
    blocks.append(py::make_tuple(m.obs_block_names[i], m.obs_block_sizes[i]));
  d["obs_blocks"] = blocks;
  // Each block's fields in order, (name, size) each, tiling the block (version 6).
  py::list fields;
  size_t next = 0;
  for (int i = 0; i < m.num_obs_blocks; ++i) {
    py::list block;
    for (int f = 0; f < m.obs_block_field_counts[i] && next < m.obs_field_names.size(); ++f, ++next)
      block.append(py::make_tuple(m.obs_field_names[next], m.obs_field_sizes[next]));
    fields.append(block);
  }
  d["obs_fields"] = fields;
  return d;
}

py::object observation_dict(const std::optional<Observation>& o) {
  if (!o) return py::none();
  py::dict d;
  d["tick"] = o->tick;
  d["slots"] = o->slots;
  d["obs"] = rows_to_array(o->obs);
  d["reward"] = py::array_t<float>(o->reward.size(), o->reward.data());
  d["term_names"] = o->term_names;
  d["terms"] = rows_to_array(o->terms);
  d["done"] = o->done;
  d["truncated"] = o->truncated;
  d["info"] = o->info;
  return d;
}

}  // namespace

namespace olympics::python {
py::dict result_dict(const olympics::match_result_t& r) {
  py::dict d;
  d["match_id"] = r.match_id;
  d["sport"] = r.sport;
  d["mode"] = r.mode;
  d["seed"] = r.seed;
  d["ticks"] = r.ticks;
  d["duration_s"] = r.duration_s;
  d["reason"] = r.reason;
  d["winner_team"] = r.winner_team;
  d["scores"] = r.scores;
  d["slot_team"] = r.slot_team;
  d["agent_names"] = r.agent_names;
  d["options"] = r.options;
  d["info"] = r.info;
  return d;
}
ClientOptions client_options(const std::string& lcm_url, const std::string& agent_name,
                             const std::string& policy_id, const std::string& policy_version,
                             const std::string& secret_file) {
  ClientOptions o;
  o.lcm_url = lcm_url;
  o.agent_name = agent_name;
  o.policy_id = policy_id;
  o.policy_version = policy_version;
  o.secret_file = secret_file;
  return o;
}

}  // namespace olympics::python

using olympics::python::result_dict;

PYBIND11_MODULE(_client, m) {
  m.doc() = "SMPL Olympics match client (C++ MatchClient over LCM)";
  py::register_exception<MatchError>(m, "MatchError", PyExc_RuntimeError);
  olympics::python::bind_vector_client(m);
  olympics::python::bind_native_policy(m);
  olympics::python::bind_server_listener(m);

  py::class_<MatchClient>(m, "MatchClient")
      .def(py::init([](const std::string& lcm_url, const std::string& agent_name,
                       const std::string& policy_id, const std::string& policy_version,
                       const std::string& secret_file) {
             return std::make_unique<MatchClient>(olympics::python::client_options(
                 lcm_url, agent_name, policy_id, policy_version, secret_file));
           }),
           py::arg("lcm_url") = "", py::arg("agent_name") = "python", py::arg("policy_id") = "",
           py::arg("policy_version") = "", py::arg("secret_file") = "")
      .def_property_readonly("client_id", &MatchClient::client_id)
      .def_property_readonly("ignored_errors", &MatchClient::ignored_errors)
      .def(
          "request_match",
          [](MatchClient& c, const std::string& sport, const std::string& mode, std::int64_t seed,
             double time_limit_s, bool realtime, const std::string& request_id,
             const std::string& server_id, double timeout_s, const std::string& options) {
            MatchRequest r{sport,    mode,       seed,      time_limit_s,
                           realtime, request_id, server_id, options};
            olympics::match_created_t created;
            {
              py::gil_scoped_release release;
              created = c.request_match(r, timeout_s);
            }
            return describe(created);
          },
          py::arg("sport") = "sandbox", py::arg("mode") = "1v1", py::arg("seed") = 0,
          py::arg("time_limit_s") = 0.0, py::arg("realtime") = false, py::arg("request_id") = "",
          py::arg("server_id") = "", py::arg("timeout_s") = 10.0, py::arg("options") = "")
      .def(
          "wait_assignment",
          [](MatchClient& c, const std::string& learner, double timeout_s) {
            Assignment a;
            {
              py::gil_scoped_release release;
              a = c.wait_assignment(learner, timeout_s);
            }
            py::dict d;
            d["league"] = a.league;
            d["learner"] = a.learner;
            d["game"] = a.game;
            d["match_id"] = a.match_id;
            d["slots"] = a.slots;
            d["opponent"] = a.opponent;
            return d;
          },
          py::arg("learner"), py::arg("timeout_s") = 600.0,
          "wait until a league assigns this live learner (entrant live:<learner>) a match")
      .def(
          "join",
          [](MatchClient& c, const std::string& match_id, const std::vector<int>& slots,
             double timeout_s) {
            olympics::match_created_t joined;
            {
              py::gil_scoped_release release;
              joined = c.join(match_id, slots, timeout_s);
            }
            return describe(joined);
          },
          py::arg("match_id"), py::arg("slots"), py::arg("timeout_s") = 30.0)
      .def(
          "next",
          [](MatchClient& c, double timeout_s) {
            std::optional<Observation> o;
            {
              py::gil_scoped_release release;
              o = c.next(timeout_s);
            }
            return observation_dict(o);
          },
          py::arg("timeout_s") = 60.0,
          "the next tick's observations (a dict), or None once the match is over")
      .def(
          "act",
          [](MatchClient& c, int tick,
             py::array_t<float, py::array::c_style | py::array::forcecast> actions) {
            if (actions.ndim() != 2)
              throw MatchError("BAD_ACTION", "actions must be a 2-d array (slots, action_size)");
            std::vector<std::vector<float>> rows(actions.shape(0),
                                                 std::vector<float>(actions.shape(1)));
            auto view = actions.unchecked<2>();
            for (py::ssize_t i = 0; i < actions.shape(0); ++i)
              for (py::ssize_t k = 0; k < actions.shape(1); ++k) rows[i][k] = view(i, k);
            c.act(tick, rows);
          },
          py::arg("tick"), py::arg("actions"))
      .def(
          "wait_result",
          [](MatchClient& c, double timeout_s) {
            olympics::match_result_t r;
            {
              py::gil_scoped_release release;
              r = c.wait_result(timeout_s);
            }
            return result_dict(r);
          },
          py::arg("timeout_s") = 30.0);
}
