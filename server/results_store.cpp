#include "results_store.h"

#include <sstream>
#include <stdexcept>

#include "postgres_results_store.h"
#include "sqlite_results_store.h"

namespace olympics::server {

std::unique_ptr<ResultsStore> open_results_store(const std::string& location) {
  if (location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0)
    return std::make_unique<PostgresResultsStore>(location);
  return std::make_unique<SqliteResultsStore>(location);
}

std::vector<StoredMatch> ResultsStore::recent(int limit, const std::string& sport) {
  return select(sport.empty() ? "" : "sport", sport, limit);
}

std::optional<StoredMatch> ResultsStore::find(const std::string& match_id) {
  auto rows = select("match_id", match_id, 1);
  if (rows.empty()) return std::nullopt;
  return rows.front();
}

std::string scores_to_text(const std::vector<double>& scores) {
  std::ostringstream out;
  out.precision(17);
  for (size_t i = 0; i < scores.size(); ++i) out << (i ? "," : "") << scores[i];
  return out.str();
}

std::vector<double> scores_from_text(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

}  // namespace olympics::server
