// The page: index.html with studio.css and studio.js inlined where it names them, so that one
// request (the one that carries the token in its address) loads everything.
#include <string>

#include "libshapeproc/studio/studio_server.hpp"

namespace shapeproc::studio {

namespace detail {
std::string page_file(const std::string& name);  // generated: cmake/embed_files.cmake
}  // namespace detail

namespace {

void inline_file(std::string& page, const std::string& marker, const std::string& open,
                 const std::string& file, const std::string& close) {
  const auto at = page.find(marker);
  if (at != std::string::npos)
    page.replace(at, marker.size(), open + detail::page_file(file) + close);
}

}  // namespace

const std::string& studio_page() {
  static const std::string page = [] {
    std::string html = detail::page_file("index.html");
    inline_file(html, "<!-- studio.css -->", "<style>\n", "studio.css", "</style>");
    inline_file(html, "<!-- studio.js -->", "<script>\n", "studio.js", "</script>");
    return html;
  }();
  return page;
}

}  // namespace shapeproc::studio
