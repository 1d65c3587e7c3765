#include "view_server.h"

#include <httplib.h>
#include <openssl/evp.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#ifndef OLYMPICS_VIEWER_DIR
#error "OLYMPICS_VIEWER_DIR must be defined by the build"
#endif

namespace olympics::server {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot read " + path +
                             " (the viewer's files; set OLYMPICS_VIEWER_DIR to server/viewer)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string base64(std::string_view bytes) {
  std::string out(4 * ((bytes.size() + 2) / 3), '\0');
  const int n = EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()),
                                reinterpret_cast<const unsigned char*>(bytes.data()),
                                static_cast<int>(bytes.size()));
  out.resize(n);
  return out;
}

// Replaces the one occurrence of `tag` in `page` with `with`; the page is ours, so a missing
// tag is a bug in this program.
void splice(std::string& page, const std::string& tag, const std::string& with) {
  const size_t at = page.find(tag);
  if (at == std::string::npos) throw std::logic_error("viewer page lacks " + tag);
  page.replace(at, tag.size(), with);
}

std::string inline_script(std::string code) {
  for (size_t at = 0; (at = code.find("</script", at)) != std::string::npos; at += 2)
    code.replace(at, 2, "<\\/");
  return "<script>" + code + "</script>";
}

}  // namespace

std::string viewer_directory() {
  if (const char* dir = std::getenv("OLYMPICS_VIEWER_DIR"); dir && *dir) return dir;
  return OLYMPICS_VIEWER_DIR;
}

std::string export_viewer_page(const std::string& scene_file_bytes) {
  const std::string dir = viewer_directory();
  std::string page = read_file(dir + "/index.html");
  splice(page, "<link rel=\"stylesheet\" href=\"viewer.css\">",
         "<style>" + read_file(dir + "/viewer.css") + "</style>");
  splice(page, "<script src=\"vendor/viewer-deps.js\"></script>",
         inline_script(read_file(dir + "/vendor/viewer-deps.js")));
  splice(page, "<script src=\"viewer.js\"></script>",
         "<script id=\"scene-data\" type=\"application/octet-stream\">" + base64(scene_file_bytes) +
             "</script>\n" + inline_script(read_file(dir + "/viewer.js")));
  return page;
}

struct ViewServer::Impl {
  httplib::Server http;
  std::thread thread;
  std::atomic<bool> stopping{false};
  int port = 0;

  void bind(const std::string& host, int wanted) {
    if (!http.set_mount_point("/", viewer_directory()))
      throw std::runtime_error("the viewer's files are not in " + viewer_directory() +
                               " (set OLYMPICS_VIEWER_DIR to server/viewer)");
    port =
        wanted == 0 ? http.bind_to_any_port(host) : (http.bind_to_port(host, wanted) ? wanted : -1);
    if (port <= 0)
      throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(wanted) +
                               " (in use? choose another port)");
  }
};

ViewServer::ViewServer(std::string scene_file_bytes, const std::string& host, int port)
    : impl_(std::make_unique<Impl>()) {
  auto scene = std::make_shared<const std::string>(std::move(scene_file_bytes));
  impl_->http.Get("/api/mode", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(R"({"mode":"replay","scene":"scene.bin"})", "application/json");
  });
  impl_->http.Get("/scene.bin", [scene](const httplib::Request&, httplib::Response& res) {
    res.set_content(*scene, "application/octet-stream");
  });
  impl_->bind(host, port);
}

ViewServer::ViewServer(LiveScenes& live, const std::string& host, int port)
    : impl_(std::make_unique<Impl>()) {
  Impl* impl = impl_.get();
  impl->http.Get("/api/mode", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(R"({"mode":"live"})", "application/json");
  });
  impl->http.Get("/api/matches", [&live](const httplib::Request&, httplib::Response& res) {
    res.set_content(live.list().dump(), "application/json");
  });
  impl->http.Get(R"(/api/live/(.+))",
                 [&live, impl](const httplib::Request& req, httplib::Response& res) {
                   auto scene = live.find(req.matches[1]);
                   if (!scene) {
                     res.status = 404;
                     res.set_content("no live match " + std::string(req.matches[1]) +
                                         " on this server (GET /api/matches lists them)",
                                     "text/plain");
                     return;
                   }
                   res.set_header("Cache-Control", "no-cache");
                   auto next = std::make_shared<std::uint64_t>(0);
                   res.set_chunked_content_provider(
                       "text/event-stream", [scene, next, impl](size_t, httplib::DataSink& sink) {
                         if (impl->stopping) return false;
                         LiveScene::Batch b = scene->wait(*next, std::chrono::milliseconds(500));
                         if (b.next) *next = b.next;
                         for (const auto& r : b.records) {
                           const std::string msg = "data: " + base64(r) + "\n\n";
                           if (!sink.write(msg.data(), msg.size())) return false;
                         }
                         if (b.ended) {
                           const std::string end = "event: end\ndata: \n\n";
                           sink.write(end.data(), end.size());
                           sink.done();
                         }
                         return true;
                       });
                 });
  impl->bind(host, port);
}

ViewServer::~ViewServer() { stop(); }

int ViewServer::port() const { return impl_->port; }

void ViewServer::start() {
  impl_->thread = std::thread([this] { impl_->http.listen_after_bind(); });
}

void ViewServer::run() { impl_->http.listen_after_bind(); }

void ViewServer::stop() {
  impl_->stopping = true;
  impl_->http.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

}  // namespace olympics::server
