// What the binding files of module smpl_olympics._client share.
#pragma once

#include <pybind11/pybind11.h>

#include "connection.h"
#include "olympics/match_result_t.hpp"

namespace olympics::python {

pybind11::dict result_dict(const olympics::match_result_t& r);
// The connection settings MatchClient and VectorClient take from Python.
olympics::client::ClientOptions client_options(const std::string& lcm_url,
                                               const std::string& agent_name,
                                               const std::string& policy_id,
                                               const std::string& policy_version,
                                               const std::string& secret_file);
// smpl_olympics._client.VectorClient (vector_bindings.cpp).
void bind_vector_client(pybind11::module_& m);
// smpl_olympics._client.NativePolicy (policy_bindings.cpp).
void bind_native_policy(pybind11::module_& m);
// smpl_olympics._client.listen_for_servers and DEFAULT_LCM_URL (server_bindings.cpp).
void bind_server_listener(pybind11::module_& m);

}  // namespace olympics::python
