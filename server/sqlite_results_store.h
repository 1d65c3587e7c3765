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
  std::string describe() const override { return "sqlite:" + path_; }

 private:
  void exec(const char* sql);
  std::vector<StoredMatch> select(const std::string& column, const std::string& value,
                                  int limit) override;
  std::string path_;
  sqlite3* db_ = nullptr;
  std::mutex mutex_;
};

}  // namespace olympics::server
