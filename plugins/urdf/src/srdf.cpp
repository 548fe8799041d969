// SRDF parsing with tinyxml2 (srdfdom is not packaged in Debian): only what self-collision needs, the
// <disable_collisions link1 link2 reason/> list and the <group_state> joint values.
#include <tinyxml2.h>

#include <string>

#include "internal.h"

namespace gq::urdf::internal {
namespace {

std::string attribute(const tinyxml2::XMLElement& e, const char* name) {
  const char* v = e.Attribute(name);
  return v ? std::string(v) : std::string();
}

Status parseDisabled(const tinyxml2::XMLElement& robot, SrdfData& out) {
  for (auto* e = robot.FirstChildElement("disable_collisions"); e; e = e->NextSiblingElement("disable_collisions")) {
    SrdfDisabledPair pair{attribute(*e, "link1"), attribute(*e, "link2"), attribute(*e, "reason")};
    if (pair.link1.empty() || pair.link2.empty())
      return Status::owned(StatusCode::ParseError, "malformed SRDF: <disable_collisions> on line " + std::to_string(e->GetLineNum()) +
                                " needs both link1 and link2");
    out.disabled.push_back(std::move(pair));
  }
  return {};
}

Status parseGroupStates(const tinyxml2::XMLElement& robot, SrdfData& out) {
  for (auto* g = robot.FirstChildElement("group_state"); g; g = g->NextSiblingElement("group_state")) {
    SrdfGroupState state{attribute(*g, "name"), {}};
    for (auto* j = g->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
      double value = 0;
      if (j->QueryDoubleAttribute("value", &value) != tinyxml2::XML_SUCCESS || attribute(*j, "name").empty())
        return Status::owned(StatusCode::ParseError, "malformed SRDF: <joint> of group_state '" + state.name + "' on line " +
                                  std::to_string(j->GetLineNum()) + " needs a name and a numeric value");
      state.values.emplace_back(attribute(*j, "name"), value);
    }
    out.states.push_back(std::move(state));
  }
  return {};
}

}  // namespace

Status parseSrdf(const std::string& xml, SrdfData& out) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    return Status::owned(StatusCode::ParseError, std::string("malformed SRDF: XML error on line ") + std::to_string(doc.ErrorLineNum()) +
                              ": " + doc.ErrorStr());
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot) return Status::parseError("malformed SRDF: no <robot> root element");
  SrdfData data;
  Status s = parseDisabled(*robot, data);
  if (s.ok()) s = parseGroupStates(*robot, data);
  if (s.ok()) out = std::move(data);
  return s;
}

}  // namespace gq::urdf::internal
