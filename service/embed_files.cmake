# Writes OUTPUT: a C++ source defining bezier::service::find_static_file() over every
# file in DIRECTORY, each as a raw string literal. Run at build time (see
# service/CMakeLists.txt), so editing a playground file rebuilds the binary.
file(GLOB files RELATIVE ${DIRECTORY} ${DIRECTORY}/*)
list(SORT files)
set(entries "")
foreach(name IN LISTS files)
  file(READ ${DIRECTORY}/${name} content)
  string(FIND "${content}" ")bezier_file\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${name} contains the raw-string delimiter )bezier_file\"")
  endif()
  get_filename_component(ext ${name} LAST_EXT)
  set(type "application/octet-stream")
  if(ext STREQUAL ".html")
    set(type "text/html; charset=utf-8")
  elseif(ext STREQUAL ".js" OR ext STREQUAL ".mjs")
    set(type "text/javascript; charset=utf-8")
  elseif(ext STREQUAL ".css")
    set(type "text/css; charset=utf-8")
  elseif(ext STREQUAL ".svg")
    set(type "image/svg+xml")
  elseif(ext STREQUAL ".json")
    set(type "application/json")
  endif()
  string(APPEND entries "    {\"/playground/${name}\", {R\"bezier_file(${content})bezier_file\", \"${type}\"}},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from service/playground/ by service/embed_files.cmake: do not edit.
#include <array>
#include <utility>

#include \"service/static_files.hpp\"

namespace bezier::service {

namespace {
const std::pair<std::string_view, StaticFile> kFiles[] = {
${entries}    {\"\", {\"\", \"\"}},
};
}  // namespace

std::optional<StaticFile> find_static_file(std::string_view path) noexcept {
  if (path == \"/\") path = \"/playground/index.html\";
  for (const auto& [name, file] : kFiles) {
    if (!name.empty() && name == path) return file;
  }
  return std::nullopt;
}

}  // namespace bezier::service
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
