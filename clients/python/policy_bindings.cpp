// smpl_olympics._client.NativePolicy: the policies olympics-agent plays (zero, random, scripted,
// mlp:FILE), callable from Python, so a trainer can play against the scripted baseline in
// process or learn a residual on top of it with the very code the agent runs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "policies.h"

namespace py = pybind11;

namespace olympics::python {
namespace {

class NativePolicy {
 public:
  NativePolicy(const std::string& name, client::MatchInfo info, std::uint64_t seed)
      : info_(std::move(info)), policy_(client::make_policy(name, seed)) {
    restart();
  }
  // A new match begins (a scripted player forgets its last point).
  void restart() { policy_->start(info_); }
  py::array_t<float> act(py::array_t<float, py::array::c_style | py::array::forcecast> obs) {
    if (obs.ndim() != 1 || obs.shape(0) != info_.observation.total())
      throw std::invalid_argument("NativePolicy.act: the observation must be a vector of " +
                                  std::to_string(info_.observation.total()) + " floats");
    py::array_t<float> action(info_.action_size);
    policy_->act(std::span<const float>(obs.data(), obs.shape(0)),
                 std::span<float>(action.mutable_data(), info_.action_size));
    return action;
  }

 private:
  client::MatchInfo info_;
  std::unique_ptr<client::Policy> policy_;
};

// The layout of a catalog mode's "observation" list: blocks with name, size and fields (each
// with name and size).
client::ObservationLayout layout_of(const py::list& observation) {
  std::vector<std::string> names, field_names;
  std::vector<int> sizes, counts, field_sizes;
  for (const auto& item : observation) {
    const auto block = item.cast<py::dict>();
    names.push_back(block["name"].cast<std::string>());
    sizes.push_back(block["size"].cast<int>());
    const py::list fields =
        block.contains("fields") ? block["fields"].cast<py::list>() : py::list();
    counts.push_back(static_cast<int>(fields.size()));
    for (const auto& f : fields) {
      field_names.push_back(f["name"].cast<std::string>());
      field_sizes.push_back(f["size"].cast<int>());
    }
  }
  return client::ObservationLayout(names, sizes, counts, field_names, field_sizes);
}

}  // namespace

void bind_native_policy(py::module_& m) {
  py::class_<NativePolicy>(m, "NativePolicy")
      .def(py::init([](const std::string& name, const std::string& sport, const std::string& mode,
                       const py::list& observation, int action_size, double control_hz,
                       std::uint64_t seed) {
             client::MatchInfo info{sport, mode, 1.0 / control_hz, layout_of(observation),
                                    action_size};
             return std::make_unique<NativePolicy>(name, std::move(info), seed);
           }),
           py::arg("name"), py::arg("sport"), py::arg("mode"), py::arg("observation"),
           py::arg("action_size"), py::arg("control_hz") = 30.0, py::arg("seed") = 1)
      .def("restart", &NativePolicy::restart)
      .def("act", &NativePolicy::act, py::arg("observation"));
}

}  // namespace olympics::python
