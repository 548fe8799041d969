#pragma once
// Result -> one output line: {"id":…,"ok":…,"ns":…, query fields…} or {"id":…,"ok":false,"error":…,"ns":…}.
#include <string>

#include <nlohmann/json.hpp>

#include "result.h"

namespace gq::cases {

// Keys keep their insertion order so every line starts with id and ok.
nlohmann::ordered_json resultToJson(const nlohmann::json& id, const Result& result);
// The line's text. Numbers print as the shortest decimal that reads back to the same double (at most
// max_digits10 = 17 significant digits): no precision is lost.
std::string resultLine(const nlohmann::json& id, const Result& result);

}  // namespace gq::cases
