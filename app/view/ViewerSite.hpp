// What `simswift view` serves (docs/viewer.md, "The server's API"): the
// page's files from the viewer folder, three.js from its installed folder,
// and the recording as JSON:
//   /api/info                          the file, time range, metadata, channels
//   /api/messages?topic=T&from=&to=&max=N   T's messages with from <= t <= to
//                                      (ns), evenly thinned to at most N
//   /api/at?topic=T&t=NS               T's last message at or before t (else its first)
// A message is {"t": log time in ns, "data": its JSON payload as recorded}.
// Only fixed names are served: a file of the viewer folder by its plain
// name (letters, digits, '.', '-', '_'; no '/'), two files of three.js.
#pragma once

#include <string>

#include "app/view/HttpServer.hpp"
#include "app/view/Mcap.hpp"

namespace simswift::view {

class ViewerSite {
 public:
  // `file`: the recording, its JSON payloads already checked
  // (checkPayloads); `viewer_dir`: the page's files; `three_dir`: three.js's.
  ViewerSite(const McapFile& file, std::string viewer_dir, std::string three_dir);
  HttpResponse handle(const HttpRequest& request) const;

 private:
  HttpResponse info() const;
  HttpResponse messages(const HttpRequest& r) const;
  HttpResponse at(const HttpRequest& r) const;
  HttpResponse file(const std::string& path, const std::string& type) const;

  const McapFile& file_;
  std::string viewer_dir_, three_dir_;
};

// Every payload of a "json" channel checked as JSON; McapError (the file,
// the payload's byte offset) for the first that is not.
void checkPayloads(const McapFile& file);

}  // namespace simswift::view
