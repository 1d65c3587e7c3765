#include "fleet_snapshots.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace olympics::selfplay {
namespace {

constexpr const char* kFilePrefix = "mlp:";

bool is_file_entrant(const Entrant& e) { return e.policy.rfind(kFilePrefix, 0) == 0; }

std::string file_of(const Entrant& e) { return e.policy.substr(std::string(kFilePrefix).size()); }

}  // namespace

void upload_snapshots(FixtureQueue& queue, const TournamentSpec& spec) {
  const auto stored = queue.snapshot_policies(spec.name);
  for (const auto& e : spec.entrants) {
    if (!is_file_entrant(e) || std::find(stored.begin(), stored.end(), e.policy) != stored.end())
      continue;
    std::ifstream in(file_of(e), std::ios::binary);
    if (!in)
      throw std::invalid_argument("snapshot " + file_of(e) + " of entrant " + e.name +
                                  " cannot be read; the fleet's cells get it from the database, "
                                  "so it must be readable where the run is queued");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    queue.store_snapshot(spec.name, e.policy, bytes.str());
  }
}

std::map<std::string, std::string> fetch_snapshots(FixtureQueue& queue, const TournamentSpec& spec,
                                                   const std::string& cache_dir) {
  namespace fs = std::filesystem;
  std::map<std::string, std::string> local;
  const fs::path folder = fs::path(cache_dir) / spec.name;
  for (const auto& e : spec.entrants) {
    if (!is_file_entrant(e)) continue;
    // Named by a hash of the stored policy (two runs' files may share a name) and the file's
    // own name (so the workers' logs stay readable).
    const fs::path file = folder / (std::to_string(std::hash<std::string>{}(e.policy)) + "-" +
                                    fs::path(file_of(e)).filename().string());
    if (!fs::exists(file)) {
      auto bytes = queue.snapshot(spec.name, e.policy);
      if (!bytes) continue;
      fs::create_directories(folder);
      const fs::path partial = file.string() + ".partial";
      std::ofstream out(partial, std::ios::binary);
      out << *bytes;
      if (!out.flush())
        throw std::invalid_argument("cannot write the snapshot cache " + partial.string() +
                                    " (a full disk, or a folder the cell may not write)");
      out.close();
      fs::rename(partial, file);  // a worker never reads half a file
    }
    local[e.policy] = file.string();
  }
  return local;
}

}  // namespace olympics::selfplay
