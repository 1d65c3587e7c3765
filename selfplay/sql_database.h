// A small SQL connection for the league's state: a SQLite file or a PostgreSQL URL, one dialect
// for both (placeholders $1..$n, types both accept), values passed and returned as text.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace olympics::selfplay {

class SqlDatabase {
 public:
  using Row = std::vector<std::string>;  // NULL reads as ""
  virtual ~SqlDatabase() = default;
  // One statement with $1..$n bound to params; the rows it returns.
  virtual std::vector<Row> query(const std::string& sql,
                                 const std::vector<std::string>& params = {}) = 0;
  // Several statements without parameters (a schema).
  virtual void script(const std::string& sql) = 0;
  virtual std::string describe() const = 0;  // the location, without a password
};

// "postgresql://..." or "postgres://..." -> PostgreSQL, anything else a SQLite file. Throws
// std::runtime_error with what to check when it cannot be opened.
std::unique_ptr<SqlDatabase> open_sql_database(const std::string& location);

}  // namespace olympics::selfplay
