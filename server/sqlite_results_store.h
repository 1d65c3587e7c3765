#pragma once

#include <sqlite3.h>

#include <mutex>

#include "results_store.h"

namespace olympics::server {

class SqliteResultsStore : public ResultsStore {
 public:
  explicit SqliteResultsStore(const std::string& path);
  ~SqliteResultsStore() override;
  void record(const StoredMatch& match) override;
  std::vector<StoredMatch> recent(int limit, const std::string& sport) override;
  std::optional<StoredMatch> find(const std::string& match_id) override;
  std::string describe() const override { return "sqlite:" + path_; }

 private:
  void exec(const char* sql);
  std::vector<StoredMatch> query_matches(const std::string& where,
                                         const std::vector<std::string>& args, int limit);
  std::string path_;
  sqlite3* db_ = nullptr;
  std::mutex mutex_;
};

}  // namespace olympics::server
