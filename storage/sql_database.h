// A small SQL connection, the one way the project talks to its databases (the server's results,
// the league's state): a SQLite file or a PostgreSQL URL, one dialect for both (placeholders
// $1..$n, types both accept), values passed and returned as text.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace olympics::sql {

class SqlDatabase {
 public:
  using Row = std::vector<std::string>;  // NULL reads as ""
  virtual ~SqlDatabase() = default;
  // One statement with $1..$n bound to params; the rows it returns.
  virtual std::vector<Row> query(const std::string& sql,
                                 const std::vector<std::string>& params = {}) = 0;
  // Several statements without parameters (a schema).
  virtual void script(const std::string& sql) = 0;
  // A schema of CREATE ... IF NOT EXISTS statements, safe when several processes make it at once
  // (PostgreSQL's IF NOT EXISTS is not: two racing creators fail on a duplicate type key).
  virtual void create_schema(const std::string& sql) { script(sql); }
  // Runs `work` in one transaction: committed if it returns, rolled back (and rethrown) if it
  // throws.
  void transaction(const std::function<void()>& work);
  virtual std::string describe() const = 0;  // the location, without a password
};

// Adds `column` to `table` (a store made before the column existed); nothing when it is there.
// Names come from the program, never from users.
void add_column_if_missing(SqlDatabase& db, const std::string& table, const std::string& column,
                           const std::string& definition);

// A double as text that reads back to the same double (17 significant digits).
std::string exact_text(double value);

// How much a SQLite commit survives (PostgreSQL commits are always durable): a crash of the
// process (WAL, synchronous=NORMAL), or also a power loss (synchronous=FULL, an fsync per commit).
enum class Durability { ProcessCrash, PowerLoss };

// "postgresql://..." or "postgres://..." -> PostgreSQL, anything else a SQLite file. Throws
// std::runtime_error with what to check when it cannot be opened.
std::unique_ptr<SqlDatabase> open_sql_database(const std::string& location,
                                               Durability durability = Durability::PowerLoss);

}  // namespace olympics::sql
