#include "match_client.h"

#include "channels.h"

namespace olympics::client {

olympics::match_created_t request_match(Connection& c, const MatchRequest& r, double timeout_s) {
  const std::string id = r.request_id.empty() ? c.client_id() + "-req" : r.request_id;
  const auto req = Connection::request_message(r, id);
  c.take_errors();
  const auto deadline = Connection::Clock::now() + seconds(timeout_s);
  auto next_send = Connection::Clock::now();
  for (;;) {
    if (auto created = c.take_created(id)) return *created;
    if (auto e = c.take_request_error(id)) throw MatchError(e->code, e->message);
    auto now = Connection::Clock::now();
    if (now >= deadline)
      throw MatchError("TIMEOUT", "no server answered the request for " + r.sport + " " + r.mode +
                                      " within " + std::to_string(timeout_s) +
                                      " s; is olympics-server running on " + c.transport().url() +
                                      "?" + c.silence_hint());
    if (now >= next_send) {
      c.send_request(req);
      next_send = now + seconds(0.25);
    }
    c.pump(std::min(deadline, next_send));
  }
}

olympics::match_created_t join_match(Connection& c, const std::string& match_id,
                                     const std::vector<int>& slots, double timeout_s) {
  c.take_join_reply(match_id);  // an answer to an earlier join is no answer to this one
  const auto deadline = Connection::Clock::now() + seconds(timeout_s);
  auto next_send = Connection::Clock::now();
  for (;;) {
    if (auto reply = c.take_join_reply(match_id)) {
      if (reply->accepted) return reply->match;
      std::string code = "REFUSED";
      for (const auto& e : c.take_errors())
        if (e.match_id == match_id) code = e.code;
      throw MatchError(code, reply->reason);
    }
    if (auto e = c.fatal_error(match_id, /*joining=*/true)) throw MatchError(e->code, e->message);
    auto now = Connection::Clock::now();
    if (now >= deadline)
      throw MatchError("TIMEOUT", "no answer to the join of match " + match_id + " within " +
                                      std::to_string(timeout_s) + " s" + c.silence_hint());
    if (now >= next_send) {
      c.send_join(match_id, slots);
      next_send = now + seconds(0.25);
    }
    c.pump(std::min(deadline, next_send));
  }
}

MatchClient::MatchClient(const ClientOptions& options) : connection_(options) {}

olympics::match_created_t MatchClient::request_match(const MatchRequest& r, double timeout_s) {
  return client::request_match(connection_, r, timeout_s);
}

Assignment MatchClient::wait_assignment(const std::string& learner, double timeout_s) {
  const auto deadline = Connection::Clock::now() + seconds(timeout_s);
  for (;;) {
    if (auto a = connection_.take_assignment(learner)) return *a;
    if (Connection::Clock::now() >= deadline)
      throw MatchError("TIMEOUT", "no league assigned a match to learner \"" + learner +
                                      "\" within " + std::to_string(timeout_s) +
                                      " s; is it an entrant (live:" + learner + ")?");
    connection_.pump(deadline);
  }
}

olympics::match_created_t MatchClient::join(const std::string& match_id,
                                            const std::vector<int>& slots, double timeout_s) {
  auto match = join_match(connection_, match_id, slots, timeout_s);
  session_.reset();  // a client may play one match after another: forget the previous one
  connection_.take_errors();
  session_ = std::make_unique<MatchSession>(connection_, match, slots);
  return match;
}

MatchSession& MatchClient::session(const char* what) {
  if (!session_) throw MatchError("NOT_JOINED", std::string("join a match before ") + what);
  return *session_;
}

const olympics::match_created_t& MatchClient::match() const {
  static const olympics::match_created_t none{};
  return session_ ? session_->match() : none;
}

std::optional<Observation> MatchClient::next(double timeout_s) {
  MatchSession& s = session("asking for observations");
  const auto deadline = Connection::Clock::now() + seconds(timeout_s);
  while (!s.has_observation()) {
    if (s.ended_without_final_observation()) return std::nullopt;
    if (Connection::Clock::now() >= deadline)
      throw MatchError("TIMEOUT", "no observation from match " + s.match().match_id + " for " +
                                      std::to_string(timeout_s) + " s: the server may be gone");
    s.maintain();
    connection_.pump(deadline);
  }
  return s.take_observation();
}

void MatchClient::act(int tick, const std::vector<std::vector<float>>& actions) {
  session("acting").act(tick, actions);
}

const olympics::match_result_t& MatchClient::wait_result(double timeout_s) {
  MatchSession& s = session("waiting for a result");
  const auto deadline = Connection::Clock::now() + seconds(timeout_s);
  while (!s.result()) {
    if (Connection::Clock::now() >= deadline)
      throw MatchError("TIMEOUT", "no result for match " + s.match().match_id + " within " +
                                      std::to_string(timeout_s) + " s");
    s.maintain();
    connection_.pump(deadline);
  }
  connection_.pump(Connection::Clock::now());  // an error about storing it comes just before
  s.maintain();                                // the result: STORE_FAILED throws here
  return *s.result();
}

std::optional<olympics::match_result_t> MatchClient::result() const {
  if (!session_ || !session_->result()) return std::nullopt;
  return *session_->result();
}

}  // namespace olympics::client
