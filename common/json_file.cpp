#include "common/json_file.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "common/input_error.hpp"
#include "common/printable_text.hpp"

namespace common {
namespace {

using nlohmann::json;

/// Where the parser is: one frame per open object or array.
struct Frame {
  bool array = false;
  std::string key;        ///< objects: the last key read
  long index = 0;         ///< arrays: the element being read
  std::set<std::string> keys;
};

std::string path_text(const std::vector<Frame>& frames) {
  std::string path;
  for (const Frame& f : frames) {
    if (f.array) path += "[" + std::to_string(f.index) + "]";
    else if (!f.key.empty()) path += (path.empty() ? "" : ".") + f.key;
  }
  return path;
}

/// nlohmann's message without its "[json.exception.xxx.nnn] " tag.
std::string without_tag(const std::string& what) {
  const auto tag = what.find("] ");
  return tag == std::string::npos ? what : what.substr(tag + 2);
}

}  // namespace

json parse_json_text(const std::string& text, const std::string& shown) {
  std::vector<Frame> frames;
  auto element_done = [&] {
    if (!frames.empty() && frames.back().array) ++frames.back().index;
  };
  const json::parser_callback_t track = [&](int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start: frames.push_back(Frame{}); break;
      case json::parse_event_t::array_start: frames.push_back(Frame{true, {}, 0, {}}); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!frames.empty()) frames.pop_back();
        element_done();
        break;
      case json::parse_event_t::key: {
        Frame& f = frames.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second)
          throw InputError(shown, "key \"" + printable(f.key) + "\" appears twice in one object" +
                                      (frames.size() > 1 ? " (in " + path_text({frames.begin(), frames.end() - 1}) + ")" : ""));
        break;
      }
      case json::parse_event_t::value: element_done(); break;
    }
    return true;
  };
  try {
    return json::parse(text, track, true, /*ignore_comments=*/false);
  } catch (const json::out_of_range& e) {
    // 406: a number too large for a double; the key is the one being read.
    const std::string path = path_text(frames);
    throw InputError(path.empty() ? shown : shown + ": " + path,
                     printable(without_tag(e.what())) + " (the value does not fit a double)");
  } catch (const json::parse_error& e) {
    throw InputError(shown, "invalid JSON (truncated file?): " + printable(without_tag(e.what())));
  }
}

json parse_json_file(const std::filesystem::path& file, const std::string& shown) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(shown, "input file not found or not readable (looked for " + file.string() + ")");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(shown, "reading the file failed");
  return parse_json_text(buffer.str(), shown);
}

}  // namespace common
