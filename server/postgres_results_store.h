#pragma once

#include <libpq-fe.h>

#include <mutex>

#include "results_store.h"

namespace olympics::server {

class PostgresResultsStore : public ResultsStore {
 public:
  explicit PostgresResultsStore(const std::string& url);
  ~PostgresResultsStore() override;
  void record(const StoredMatch& match) override;
  std::vector<StoredMatch> recent(int limit, const std::string& sport) override;
  std::optional<StoredMatch> find(const std::string& match_id) override;
  std::string describe() const override { return shown_url_; }

 private:
  struct Result;
  Result exec(const std::string& sql, const std::vector<std::string>& params = {});
  std::vector<StoredMatch> query_matches(const std::string& where,
                                         const std::vector<std::string>& params, int limit);
  std::string shown_url_;  // without the password
  PGconn* conn_ = nullptr;
  std::mutex mutex_;
};

}  // namespace olympics::server
