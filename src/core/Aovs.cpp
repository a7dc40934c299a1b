#include "core/Aovs.h"

#include "core/Error.h"
#include "core/Text.h"

namespace lenslab {

const std::vector<std::string>& aovNames() {
  static const std::vector<std::string> names{"depth", "normal", "albedo", "instance", "flow"};
  return names;
}

std::vector<std::string> AovSelection::names() const {
  std::vector<std::string> out;
  const bool on[] = {depth, normal, albedo, instance, flow};
  for (std::size_t i = 0; i < aovNames().size(); ++i)
    if (on[i]) out.push_back(aovNames()[i]);
  return out;
}

AovSelection parseAovs(const std::vector<std::string>& names, const std::string& option) {
  AovSelection s;
  for (const std::string& name : names) {
    if (name == "depth")
      s.depth = true;
    else if (name == "normal")
      s.normal = true;
    else if (name == "albedo")
      s.albedo = true;
    else if (name == "instance")
      s.instance = true;
    else if (name == "flow")
      s.flow = true;
    else {
      std::string valid;
      for (const std::string& n : aovNames()) valid += (valid.empty() ? "" : ", ") + n;
      throw InputError(cat(option, " ", name, ": unknown AOV; valid are ", valid, " (a list: depth,normal)"));
    }
  }
  return s;
}

std::string aovList(const AovSelection& selection) {
  std::string list;
  for (const std::string& n : selection.names()) list += (list.empty() ? "" : ",") + n;
  return list;
}

}  // namespace lenslab
