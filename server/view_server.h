// The viewer's HTTP side (docs/viewer.md): serves the page in server/viewer, and either one
// match's scene track (`olympics-server view`) or the matches this server is playing, live, as
// server-sent events (`serve --view-port`). Its threads only read what the stepping threads
// published (live_scenes.h); they never touch a match.
#pragma once

#include <memory>
#include <string>

#include "live_scenes.h"

namespace olympics::server {

// Where the page's files are: $OLYMPICS_VIEWER_DIR, else the source tree's server/viewer.
std::string viewer_directory();

// One self-contained HTML file: the page, its scripts and the scene track (the .scene file's
// bytes, zstd) inlined, to open from disk or share.
std::string export_viewer_page(const std::string& scene_file_bytes);

class ViewServer {
 public:
  // Serves one recorded match.
  ViewServer(std::string scene_file_bytes, const std::string& host, int port);
  // Serves the live matches of a server.
  ViewServer(LiveScenes& live, const std::string& host, int port);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  int port() const;  // the bound port (port 0 asks for any free one)
  void start();      // serves on a thread of its own until stop()
  void run();        // serves on this thread until stop()
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace olympics::server
