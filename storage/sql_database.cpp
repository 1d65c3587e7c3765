#include "sql_database.h"

#include <libpq-fe.h>
#include <sqlite3.h>

#include <cstdio>
#include <regex>
#include <stdexcept>

namespace olympics::sql {
namespace {

class SqliteDatabase : public SqlDatabase {
 public:
  SqliteDatabase(const std::string& path, Durability durability) : path_(path) {
    if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) {
      std::string why = sqlite3_errmsg(db_);
      sqlite3_close(db_);
      throw std::runtime_error("cannot open database " + path + ": " + why +
                               " (check that the folder exists and is writable)");
    }
    sqlite3_busy_timeout(db_, 5000);
    script(durability == Durability::PowerLoss
               ? "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;"
               : "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;");
  }
  ~SqliteDatabase() override { sqlite3_close(db_); }

  std::vector<Row> query(const std::string& sql, const std::vector<std::string>& params) override {
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &stmt, nullptr) != SQLITE_OK)
      throw std::runtime_error(path_ + ": " + sqlite3_errmsg(db_));
    std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)> guard(stmt, &sqlite3_finalize);
    for (size_t i = 0; i < params.size(); ++i) {
      // $n is a named parameter in SQLite: bind it by its name, wherever it appears.
      char name[32];
      std::snprintf(name, sizeof name, "$%zu", i + 1);
      int index = sqlite3_bind_parameter_index(stmt, name);
      if (index > 0) sqlite3_bind_text(stmt, index, params[i].c_str(), -1, SQLITE_TRANSIENT);
    }
    std::vector<Row> rows;
    for (;;) {
      int rc = sqlite3_step(stmt);
      if (rc == SQLITE_DONE) break;
      if (rc != SQLITE_ROW) throw std::runtime_error(path_ + ": " + sqlite3_errmsg(db_));
      Row row;
      for (int c = 0; c < sqlite3_column_count(stmt); ++c) {
        auto* t = sqlite3_column_text(stmt, c);
        row.emplace_back(t ? reinterpret_cast<const char*>(t) : "");
      }
      rows.push_back(std::move(row));
    }
    return rows;
  }

  void script(const std::string& sql) override {
    char* error = nullptr;
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
      std::string why = error ? error : "?";
      sqlite3_free(error);
      throw std::runtime_error(path_ + ": " + why);
    }
  }

  std::string describe() const override { return "sqlite:" + path_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

class PostgresDatabase : public SqlDatabase {
 public:
  explicit PostgresDatabase(const std::string& url)
      : shown_(std::regex_replace(url, std::regex(":[^:@/]*@"), ":***@")),
        conn_(PQconnectdb(url.c_str())) {
    if (PQstatus(conn_) != CONNECTION_OK) {
      std::string why = PQerrorMessage(conn_);
      PQfinish(conn_);
      throw std::runtime_error(
          "cannot connect to " + shown_ + ": " + why +
          "(check the URL, that the server runs and that the role may log in)");
    }
    script("SET client_min_messages TO WARNING");
  }
  ~PostgresDatabase() override { PQfinish(conn_); }

  std::vector<Row> query(const std::string& sql, const std::vector<std::string>& params) override {
    std::vector<const char*> values;
    for (const auto& p : params) values.push_back(p.c_str());
    std::unique_ptr<PGresult, decltype(&PQclear)> r(
        PQexecParams(conn_, sql.c_str(), static_cast<int>(values.size()), nullptr, values.data(),
                     nullptr, nullptr, 0),
        &PQclear);
    auto status = PQresultStatus(r.get());
    if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)
      throw std::runtime_error(shown_ + ": " + PQerrorMessage(conn_));
    std::vector<Row> rows(PQntuples(r.get()));
    for (int i = 0; i < PQntuples(r.get()); ++i)
      for (int c = 0; c < PQnfields(r.get()); ++c) rows[i].emplace_back(PQgetvalue(r.get(), i, c));
    return rows;
  }

  void script(const std::string& sql) override {
    std::unique_ptr<PGresult, decltype(&PQclear)> r(PQexec(conn_, sql.c_str()), &PQclear);
    auto status = PQresultStatus(r.get());
    if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK)
      throw std::runtime_error(shown_ + ": " + PQerrorMessage(conn_));
  }

  // One transaction (PQexec runs a multi-statement string as one) holding an advisory lock that
  // every schema maker of this project takes first, so makers run one after another.
  void create_schema(const std::string& sql) override {
    script("SELECT pg_advisory_xact_lock(" + std::to_string(kSchemaLock) + ");\n" + sql);
  }

  std::string describe() const override { return shown_; }

 private:
  static constexpr long long kSchemaLock = 0x4f4c594d50494353;  // "OLYMPICS"
  std::string shown_;
  PGconn* conn_;
};

}  // namespace

void SqlDatabase::transaction(const std::function<void()>& work) {
  script("BEGIN");
  try {
    work();
    script("COMMIT");
  } catch (...) {
    script("ROLLBACK");
    throw;
  }
}

void add_column_if_missing(SqlDatabase& db, const std::string& table, const std::string& column,
                           const std::string& definition) {
  try {
    db.query("SELECT " + column + " FROM " + table + " LIMIT 0");
  } catch (const std::runtime_error&) {
    db.query("ALTER TABLE " + table + " ADD COLUMN " + column + " " + definition);
  }
}

std::string exact_text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

std::unique_ptr<SqlDatabase> open_sql_database(const std::string& location, Durability durability) {
  if (location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0)
    return std::make_unique<PostgresDatabase>(location);
  return std::make_unique<SqliteDatabase>(location, durability);
}

}  // namespace olympics::sql
