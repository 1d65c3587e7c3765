// An olympics-server process of its own (own LCM port, own results database and replay folder)
// for one integration test, and agent processes that talk to it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "replay.h"
#include "results_store.h"
#include "test_programs.h"

namespace olympics::testing {

class ServerFixture {
 public:
  // `results`: "" = a SQLite file in the test's folder, else a path or postgresql:// URL.
  explicit ServerFixture(std::vector<std::string> extra_args = {},
                         std::string url = unique_lcm_url(), std::string results = "",
                         std::string id = "srv")
      : url_(std::move(url)), dir_(temp_dir()) {
    if (results.empty()) results = results_path();
    std::vector<std::string> argv = {program("olympics-server"),
                                     "serve",
                                     "--lcm-url",
                                     url_,
                                     "--results",
                                     results,
                                     "--replay-dir",
                                     dir_ + "/replays",
                                     "--id",
                                     id};
    argv.insert(argv.end(), extra_args.begin(), extra_args.end());
    // A loaded CI machine can stall a client for seconds: unless a test is about deadlines, the
    // server waits for actions and silence far longer than any test runs, so a slow moment
    // changes no result (tests wait for conditions, not for clocks).
    auto given = [&](const char* flag) {
      return std::find(extra_args.begin(), extra_args.end(), flag) != extra_args.end();
    };
    for (auto [flag, patient] :
         {std::pair{"--action-deadline-ms", "600000"}, std::pair{"--max-missed-ticks", "1000"},
          std::pair{"--silent-timeout-s", "3600"}})
      if (!given("--action-deadline-ms") && !given("--max-missed-ticks") && !given(flag))
        argv.insert(argv.end(), {flag, patient});
    server_ = std::make_unique<Process>(argv, dir_ + "/server.log");
    if (!server_->wait_for_output("olympics-server", 60))
      ADD_FAILURE() << "server did not start:\n" << server_->output();
  }

  std::unique_ptr<Process> agent(const std::string& name, std::vector<std::string> args) {
    std::vector<std::string> argv = {
        program("olympics-agent"), "--lcm-url", url_, "--name", name, "--json", "--timeout", "30"};
    argv.insert(argv.end(), args.begin(), args.end());
    return std::make_unique<Process>(argv, dir_ + "/agent-" + name + ".log");
  }

  // One match between two agent processes: `common` arguments for both, then each side's own.
  // Both must exit 0 and print the same result, which is returned (empty if they did not).
  nlohmann::json two_agents(const std::vector<std::string>& common,
                            const std::vector<std::string>& first,
                            const std::vector<std::string>& second, double timeout_s = 300) {
    auto a = common, b = common;
    a.insert(a.end(), first.begin(), first.end());
    b.insert(b.end(), second.begin(), second.end());
    auto pa = agent("first", a), pb = agent("second", b);
    const bool ok = pa->wait(timeout_s) == 0 && pb->wait(timeout_s) == 0;
    EXPECT_TRUE(ok) << "first:\n" << pa->output() << "\nsecond:\n" << pb->output();
    if (!ok) return nlohmann::json::object();
    const nlohmann::json result = agent_result(*pa);
    EXPECT_EQ(result, agent_result(*pb));
    return result;
  }

  // The JSON result line an agent printed (empty object if none).
  static nlohmann::json agent_result(const Process& p) {
    std::string out = p.output();
    size_t at = out.find("{\"agents\"");
    if (at == std::string::npos) return nlohmann::json::object();
    return nlohmann::json::parse(out.substr(at, out.find('\n', at) - at));
  }

  std::unique_ptr<server::ResultsStore> store() {
    return server::open_results_store(results_path());
  }
  server::Replay replay(const std::string& match_id) {
    return server::read_replay(dir_ + "/replays/" + match_id + ".replay");
  }
  std::string results_path() const { return dir_ + "/results.db"; }
  const std::string& url() const { return url_; }
  const std::string& dir() const { return dir_; }
  Process& server() { return *server_; }

 private:
  std::string url_, dir_;
  std::unique_ptr<Process> server_;
};

}  // namespace olympics::testing
