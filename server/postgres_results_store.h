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
  std::string describe() const override { return shown_url_; }

 private:
  struct Result;
  Result exec(const std::string& sql, const std::vector<std::string>& params = {});
  std::vector<StoredMatch> select(const std::string& column, const std::string& value,
                                  int limit) override;
  std::string shown_url_;  // without the password
  PGconn* conn_ = nullptr;
  std::mutex mutex_;
};

}  // namespace olympics::server
