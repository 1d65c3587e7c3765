// Child processes: start a program with its output in a file, wait, signal, read the output.
// The league starts its policy workers with it; the integration tests their servers and agents.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace olympics {

class Process {
 public:
  // Starts `argv` with stdout and stderr going to `log_path`.
  Process(const std::vector<std::string>& argv, const std::string& log_path);
  ~Process();  // SIGKILLs it if still running
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  // Exit code, or -1 if it is still running after timeout_s (it is left running).
  int wait(double timeout_s);
  void signal(int sig);
  bool running();
  std::string output() const;
  // Waits until the output contains `text`; false on timeout or exit.
  bool wait_for_output(const std::string& text, double timeout_s);
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  int status_ = -1;
  bool reaped_ = false;
  std::string log_path_;
};

// The installed program `name` in the folder of the running one (build/bin/olympics-agent
// beside build/bin/olympics-league).
std::string program_beside_this_one(const std::string& name);

// A fresh empty directory under /tmp.
std::string temp_dir();

}  // namespace olympics
