#include "scheduler.h"

#include <algorithm>
#include <stdexcept>

#include "heat_rounds.h"
#include "heats.h"

namespace olympics::selfplay {
namespace {

class TournamentScheduler : public Scheduler {
 public:
  Verdict schedule(TournamentSpec& spec, const std::vector<Game>& games,
                   std::vector<Pairing>& out) override {
    for (const auto& g : games)
      if (g.status != GameStatus::Done) return Verdict::Wait;  // rounds start together
    const int seats = ranked_seats(spec.mode);
    if (seats > 2) return schedule_heats(spec, games, seats, out);
    const Verdict verdict = schedule_pairs(spec, games, out);
    // A ranked mode of two (competition_2) pairs as two teams do, each pair a ranked fixture.
    if (seats == 2)
      for (auto& p : out)
        if (p.away >= 0) p.seats = {p.home, p.away};
    return verdict;
  }

 private:
  // Heats of N for a ranked competition_N: round-robin (every entrant meets every other in some
  // heat; twice: double-round-robin), all heats scheduled at once; swiss and knockout a round of
  // heats at a time, from the places of the rounds before (heat_rounds.h).
  static Verdict schedule_heats(const TournamentSpec& spec, const std::vector<Game>& games,
                                int seats, std::vector<Pairing>& out) {
    const int entrants = static_cast<int>(spec.entrants.size());
    check_ranked_tournament(spec.mode, spec.format, entrants);
    if (spec.format == "swiss" || spec.format == "knockout") {
      std::vector<HeatResult> results;
      for (const auto& g : games)
        if (g.ranked()) results.push_back({g.round, g.seats, g.places});
      out = spec.format == "swiss" ? swiss_heats_round(entrants, seats, results)
                                   : knockout_heats_round(entrants, seats, results);
      return out.empty() ? Verdict::Finished : Verdict::Added;
    }
    if (!games.empty()) return Verdict::Finished;
    out = heats(entrants, seats, spec.seed, spec.format == "double-round-robin" ? 2 : 1);
    return Verdict::Added;
  }

  static Verdict schedule_pairs(TournamentSpec& spec, const std::vector<Game>& games,
                                std::vector<Pairing>& out) {
    const int n = static_cast<int>(spec.entrants.size());
    if (spec.format == "round-robin" || spec.format == "double-round-robin") {
      if (!games.empty()) return Verdict::Finished;
      out = round_robin(n, spec.format == "double-round-robin");
      return Verdict::Added;
    }
    std::vector<GameResult> results;
    int rounds = 0;
    for (const auto& g : games) {
      results.push_back({g.home, g.away, g.home_score});
      rounds = std::max(rounds, g.round + 1);
    }
    if (spec.format == "swiss") {
      if (rounds >= swiss_round_count(n)) return Verdict::Finished;
      out = swiss_round(n, rounds, results);
      return Verdict::Added;
    }
    if (spec.format != "knockout")
      throw std::invalid_argument("unknown tournament format \"" + spec.format +
                                  "\"; formats: round-robin, double-round-robin, swiss, knockout");
    std::vector<int> survivors;
    if (rounds == 0) {
      for (int i = 0; i < n; ++i) survivors.push_back(i);
    } else {
      for (size_t i = 0; i < games.size(); ++i)
        if (games[i].round == rounds - 1) survivors.push_back(knockout_winner(results[i]));
      std::sort(survivors.begin(), survivors.end());  // seed order
    }
    if (survivors.size() <= 1) return Verdict::Finished;
    out = knockout_round(survivors, rounds);
    return Verdict::Added;
  }
};

}  // namespace

std::unique_ptr<Scheduler> make_tournament_scheduler() {
  return std::make_unique<TournamentScheduler>();
}

}  // namespace olympics::selfplay
