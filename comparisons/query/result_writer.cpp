#include "result_writer.h"

namespace gq::cases {
namespace {

using OJson = nlohmann::ordered_json;

OJson vec(const Vec3d& v) { return OJson::array({v.x(), v.y(), v.z()}); }

void write(OJson&, const std::monostate&) {}

void write(OJson& j, const RaycastOut& r) {
  OJson hits = OJson::array();
  for (const RayHitOut& h : r.hits) {
    OJson hit;
    hit["distance"] = h.distance;
    if (h.position) hit["position"] = vec(*h.position);
    if (h.normal) hit["normal"] = vec(*h.normal);
    hit["faceIndex"] = h.faceIndex;
    if (h.uv) {
      hit["u"] = (*h.uv)[0];
      hit["v"] = (*h.uv)[1];
    }
    hits.push_back(std::move(hit));
  }
  j["hits"] = std::move(hits);
}

void write(OJson& j, const OverlapOut& r) { j["overlap"] = r.overlap; }

void write(OJson& j, const PenetrationOut& r) {
  j["penetrating"] = r.penetrating;
  j["direction"] = vec(r.direction);
  j["depth"] = r.depth;
}

void write(OJson& j, const DistanceOut& r) {
  j["distance"] = r.distance;
  j["point0"] = vec(r.point0);
  j["point1"] = vec(r.point1);
  j["normal"] = vec(r.normal);
}

void write(OJson& j, const PointDistanceOut& r) {
  j["distance"] = r.distance;
  j["closestPoint"] = vec(r.closestPoint);
  j["closestIndex"] = r.closestIndex;
}

void write(OJson& j, const SweepOut& r) {
  j["hit"] = r.hit;
  if (!r.hit) return;
  j["distance"] = r.distance;
  if (r.position) j["position"] = vec(*r.position);
  if (r.normal) j["normal"] = vec(*r.normal);
  j["faceIndex"] = r.faceIndex;
  j["initialOverlap"] = r.initialOverlap;
}

void write(OJson& j, const BoundsOut& r) {
  j["min"] = vec(r.min);
  j["max"] = vec(r.max);
}

}  // namespace

OJson resultToJson(const nlohmann::json& id, const Result& result) {
  OJson j;
  j["id"] = OJson::parse(id.dump());  // json -> ordered_json, unchanged
  j["ok"] = result.ok;
  if (!result.ok) {
    j["error"] = result.error;
    j["ns"] = result.ns;
    return j;
  }
  j["ns"] = result.ns;
  std::visit([&](const auto& fields) { write(j, fields); }, result.fields);
  return j;
}

std::string resultLine(const nlohmann::json& id, const Result& result) {
  // Invalid UTF-8 in an echoed string is replaced rather than thrown.
  return resultToJson(id, result).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace gq::cases
