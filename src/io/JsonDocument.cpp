#include "io/JsonDocument.h"

#include "core/Error.h"
#include "core/NumberInput.h"
#include "core/Text.h"

#include <set>
#include <vector>

namespace lenslab {

nlohmann::json parseJsonDocument(const std::string& text, const std::string& where) {
  using json = nlohmann::json;
  std::vector<std::set<std::string>> keysOfOpenObjects;
  try {
    return json::parse(text, [&](int depth, json::parse_event_t event, json& parsed) {
      if (depth > kMaxJsonDepth)
        throw InputError(cat(where, ": the JSON nests deeper than ", kMaxJsonDepth, " levels"));
      switch (event) {
        case json::parse_event_t::object_start: keysOfOpenObjects.emplace_back(); break;
        case json::parse_event_t::object_end:
          if (!keysOfOpenObjects.empty()) keysOfOpenObjects.pop_back();
          break;
        case json::parse_event_t::key:
          if (!keysOfOpenObjects.empty() && !keysOfOpenObjects.back().insert(parsed.get<std::string>()).second)
            throw InputError(cat(where, ": the key \"", excerpt(parsed.get<std::string>()),
                                 "\" is given twice in one object; keep one"));
          break;
        default: break;
      }
      return true;
    });
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number beyond double's range
    std::string what = e.what();
    if (const auto p = what.find("parse error"); p != std::string::npos)
      what = what.substr(p);
    else if (const auto end = what.find("] "); what.starts_with("[json.exception") && end != std::string::npos)
      what.erase(0, end + 2);
    // The parser quotes the token it stopped at, which may be a whole long string.
    if (what.size() > 200) what = what.substr(0, 200) + "…";
    throw InputError(cat(where, ": not valid JSON: ", what));
  }
}

}  // namespace lenslab
