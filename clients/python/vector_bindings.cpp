// smpl_olympics._client.VectorClient: the C++ VectorClient with numpy arrays in and out. Every
// batch is one set of contiguous arrays [envs, agents, ...] (no per-agent objects); blocking
// calls release the GIL.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <optional>

#include "bindings.h"
#include "vector_client.h"

namespace py = pybind11;
using namespace olympics::client;

namespace olympics::python {
namespace {

template <typename T>
py::array_t<T> array(const std::vector<T>& data, std::vector<py::ssize_t> shape) {
  py::array_t<T> out(shape);
  if (!data.empty()) std::memcpy(out.mutable_data(), data.data(), data.size() * sizeof(T));
  return out;
}

py::array_t<bool> flags(const std::vector<std::uint8_t>& data, std::vector<py::ssize_t> shape) {
  py::array_t<bool> out(shape);
  bool* at = out.mutable_data();
  for (size_t i = 0; i < data.size(); ++i) at[i] = data[i] != 0;
  return out;
}

py::dict batch_dict(const VectorClient& c, const VectorBatch& b) {
  const py::ssize_t n = static_cast<py::ssize_t>(b.envs.size()), a = c.num_agents(),
                    o = c.obs_size(), t = static_cast<py::ssize_t>(c.term_names().size());
  py::dict d;
  d["envs"] = array(b.envs, {n});
  d["obs"] = array(b.obs, {n, a, o});
  d["reward"] = array(b.reward, {n, a});
  d["terms"] = array(b.terms, {n, a, t});
  d["terminated"] = flags(b.terminated, {n, a});
  d["truncated"] = flags(b.truncated, {n, a});
  d["episode_over"] = flags(b.episode_over, {n});
  d["final_obs"] = array(b.final_obs, {n, a, o});
  d["tick"] = array(b.tick, {n});
  return d;
}

using Actions = py::array_t<float, py::array::c_style | py::array::forcecast>;

}  // namespace

void bind_vector_client(py::module_& m) {
  py::class_<VectorClient>(m, "VectorClient")
      .def(py::init([](int num_envs, const std::string& sport, const std::string& mode,
                       std::int64_t seed, double time_limit_s, bool realtime,
                       const std::string& options, const std::string& server_id,
                       const std::vector<int>& slots, const std::string& request_prefix,
                       double timeout_s, const std::string& lcm_url, const std::string& agent_name,
                       const std::string& policy_id, const std::string& policy_version,
                       const std::string& secret_file, double drop_rate,
                       const std::string& learner) {
             ClientOptions o =
                 client_options(lcm_url, agent_name, policy_id, policy_version, secret_file);
             o.drop_rate = drop_rate;
             VectorSettings v;
             v.num_envs = num_envs;
             v.request = {sport, mode, seed, time_limit_s, realtime, "", server_id, options};
             v.slots = slots;
             v.request_prefix = request_prefix;
             v.timeout_s = timeout_s;
             v.learner = learner;
             return std::make_unique<VectorClient>(o, v);
           }),
           py::arg("num_envs"), py::arg("sport"), py::arg("mode"), py::arg("seed") = 0,
           py::arg("time_limit_s") = 0.0, py::arg("realtime") = false, py::arg("options") = "",
           py::arg("server_id") = "", py::arg("slots") = std::vector<int>{},
           py::arg("request_prefix") = "", py::arg("timeout_s") = 60.0, py::arg("lcm_url") = "",
           py::arg("agent_name") = "python", py::arg("policy_id") = "",
           py::arg("policy_version") = "", py::arg("secret_file") = "", py::arg("drop_rate") = 0.0,
           py::arg("learner") = "")
      .def_property_readonly("num_envs", &VectorClient::num_envs)
      .def_property_readonly("num_agents", &VectorClient::num_agents)
      .def_property_readonly("slots", &VectorClient::slots)
      .def_property_readonly("obs_size", &VectorClient::obs_size)
      .def_property_readonly("action_size", &VectorClient::action_size)
      .def_property_readonly("term_names", &VectorClient::term_names)
      .def_property_readonly("client_id", &VectorClient::client_id)
      .def_property_readonly("ignored_errors", &VectorClient::ignored_errors)
      .def("match_id", [](const VectorClient& c, int env) { return c.match(env).match_id; })
      .def("reset",
           [](VectorClient& c) {
             const VectorBatch* b;
             {
               py::gil_scoped_release release;
               b = &c.reset();
             }
             return batch_dict(c, *b);
           })
      .def("start",
           [](VectorClient& c) {
             py::gil_scoped_release release;
             c.start();
           })
      .def(
          "step",
          [](VectorClient& c, Actions actions) {
            const VectorBatch* b;
            std::span<const float> flat(actions.data(), static_cast<size_t>(actions.size()));
            {
              py::gil_scoped_release release;
              b = &c.step(flat);
            }
            return batch_dict(c, *b);
          },
          py::arg("actions"))
      .def(
          "send",
          [](VectorClient& c, const std::vector<int>& envs, Actions actions) {
            std::span<const float> flat(actions.data(), static_cast<size_t>(actions.size()));
            py::gil_scoped_release release;
            c.send(envs, flat);
          },
          py::arg("envs"), py::arg("actions"))
      .def(
          "recv",
          [](VectorClient& c, int min_ready, std::optional<double> timeout_s) {
            const VectorBatch* b;
            {
              py::gil_scoped_release release;
              b = &c.recv(min_ready, timeout_s.value_or(-1));
            }
            return batch_dict(c, *b);
          },
          py::arg("min_ready") = 1, py::arg("timeout_s") = py::none())
      .def("take_results", [](VectorClient& c) {
        py::list out;
        for (const auto& r : c.take_results()) out.append(result_dict(r));
        return out;
      });
}

}  // namespace olympics::python
