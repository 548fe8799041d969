// Support start tables and their per-mesh registry (see support_table.h).
#include "gjk/support_table.h"

#include <algorithm>
#include <array>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>

#include "gjk/support_map.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

// Registry of built tables. An entry whose mesh has expired may be replaced (its address was reused); a live one
// never is, so a table pointer handed out stays valid while its mesh lives.
template <class T> struct StartTableRegistry {
  struct Entry {
    std::weak_ptr<const ConvexMesh<T>> mesh;
    std::unique_ptr<const SupportStartTable<T>> table;
  };
  std::shared_mutex mutex;
  std::unordered_map<const ConvexMesh<T>*, Entry> entries;
  std::size_t pruneAt = 64;

  static StartTableRegistry& instance() {
    static StartTableRegistry registry;
    return registry;
  }

  const SupportStartTable<T>* find(const std::shared_ptr<const ConvexMesh<T>>& mesh) {
    {
      std::shared_lock<std::shared_mutex> lock(mutex);
      const auto it = entries.find(mesh.get());
      if (it != entries.end() && !it->second.mesh.expired()) return it->second.table.get();
    }
    auto table = std::make_unique<const SupportStartTable<T>>(*mesh);
    std::unique_lock<std::shared_mutex> lock(mutex);
    if (entries.size() >= pruneAt) {
      for (auto it = entries.begin(); it != entries.end();) it = it->second.mesh.expired() ? entries.erase(it) : std::next(it);
      pruneAt = std::max<std::size_t>(64, 2 * entries.size());
    }
    Entry& e = entries[mesh.get()];
    // Another thread may have built it meanwhile: keep the first one (pointers to it may be in use).
    if (!e.table || e.mesh.expired()) e = {mesh, std::move(table)};
    return e.table.get();
  }
};

// Per-thread direct-mapped front of the registry: a hit costs an address compare and an expiry check (an atomic
// load), no lock. A live weak reference means the address still holds the mesh the table was built for.
template <class T> struct StartTableFront {
  static constexpr std::size_t kSlots = 16;
  struct Slot {
    const ConvexMesh<T>* key = nullptr;
    std::weak_ptr<const ConvexMesh<T>> mesh;
    const SupportStartTable<T>* table = nullptr;
  };
  std::array<Slot, kSlots> slots;

  static std::size_t slotOf(const void* p) { return (reinterpret_cast<std::uintptr_t>(p) >> 6) % kSlots; }
};

}  // namespace

template <class T> SupportStartTable<T>::SupportStartTable(const ConvexMesh<T>& hull)
    : cells_(kStartTableCells), cellsT_(T(cells_)), halfCells_(T(cells_) / T(2)),
      start_(6 * cells_ * cells_, 0) {
  const bool climb = hasAdjacency(hull);
  std::uint32_t previous = 0;
  for (std::uint32_t f = 0; f < 6; ++f)
    for (std::uint32_t i = 0; i < cells_; ++i)
      for (std::uint32_t j = 0; j < cells_; ++j) {
        // Neighbouring cells have nearby answers: each climb starts from the previous cell's vertex.
        const Vec3<T> d = cellDirection(f, i, j);
        previous = climb ? climbVertex(hull, d, previous) : bruteForceVertex(hull, d);
        start_[(f * cells_ + i) * cells_ + j] = previous;
      }
  if (climb) {
    buildClimbGraph(hull);
    settleCells(hull);
  }
}

// A cell is the convex cone spanned by its four corner directions c. Its vertex w is the support along every d of the
// cone with margin m |d| (|w| + |n|) over each neighbour n when c.(w - n) >= m |c| (|w| + |n|) at every corner (d is a
// non-negative combination of the corners, and |d| <= the combination of their norms). The climb compares dot products
// rounded within 3 eps |d| |.| each, and the lookup may place d a few eps outside its cell's cone: m = 64 eps leaves the
// climb no neighbour to move to, with room for the test's own rounding (~6 eps; in double).
template <class T> void SupportStartTable<T>::settleCells(const ConvexMesh<T>& hull) {
  using W = double;
  const W margin = W(64) * W(std::numeric_limits<T>::epsilon());
  const auto wide = [](const Vec3<T>& x) { return Eigen::Matrix<W, 3, 1>(W(x.x()), W(x.y()), W(x.z())); };
  for (std::uint32_t f = 0; f < 6; ++f)
    for (std::uint32_t i = 0; i < cells_; ++i)
      for (std::uint32_t j = 0; j < cells_; ++j) {
        std::uint32_t& entry = start_[(f * cells_ + i) * cells_ + j];
        const Eigen::Matrix<W, 3, 1> w = wide(hull.vertices[entry]);
        bool everyCorner = true;
        for (std::uint32_t corner = 0; corner < 4 && everyCorner; ++corner) {
          const T u = T(2 * (i + corner / 2)) / T(cells_) - T(1), v = T(2 * (j + corner % 2)) / T(cells_) - T(1);
          const Eigen::Matrix<W, 3, 1> c = wide(faceDirection(f, u, v));
          for (std::uint32_t k = hull.adjacencyOffsets[entry]; k < hull.adjacencyOffsets[entry + 1] && everyCorner; ++k) {
            const Eigen::Matrix<W, 3, 1> n = wide(hull.vertices[hull.adjacency[k]]);
            everyCorner = c.dot(w - n) >= margin * c.norm() * (w.norm() + n.norm());
          }
        }
        if (everyCorner) entry |= kSettled;
      }
}

template <class T> void SupportStartTable<T>::buildClimbGraph(const ConvexMesh<T>& hull) {
  constexpr std::uint32_t lanes = kClimbLanes<T>;
  const std::size_t n = hull.vertices.size();
  offsets_.assign(n + 1, 0);
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t degree = hull.adjacencyOffsets[v + 1] - hull.adjacencyOffsets[v];
    offsets_[v + 1] = offsets_[v] + (degree + lanes - 1) / lanes * lanes;
  }
  // Slots are tracked as floating-point lane values in the packed scans: exact below 2^24.
  if (offsets_[n] >= (1u << 24)) {
    offsets_.clear();
    return;
  }
  // Trailing room: a packed load never reads past the arrays.
  const std::size_t slots = offsets_[n] + lanes;
  x_.assign(slots, T(0));
  y_.assign(slots, T(0));
  z_.assign(slots, T(0));
  neighbour_.assign(slots, 0);
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t first = hull.adjacencyOffsets[v], last = hull.adjacencyOffsets[v + 1];
    for (std::uint32_t k = offsets_[v]; k < offsets_[v + 1]; ++k) {
      // Past the vertex's degree: repeat its last neighbour.
      const std::uint32_t a = std::min(first + (k - offsets_[v]), last - 1);
      const std::uint32_t u = hull.adjacency[a];
      neighbour_[k] = u;
      x_[k] = hull.vertices[u].x();
      y_[k] = hull.vertices[u].y();
      z_[k] = hull.vertices[u].z();
    }
  }
}

template <class T> Vec3<T> SupportStartTable<T>::faceDirection(std::uint32_t face, T u, T v) const {
  const T major = face % 2 == 0 ? T(1) : T(-1);
  switch (face / 2) {
    case 0: return Vec3<T>(major, u, v);
    case 1: return Vec3<T>(u, major, v);
    default: return Vec3<T>(u, v, major);
  }
}

template <class T> Vec3<T> SupportStartTable<T>::cellDirection(std::uint32_t face, std::uint32_t i, std::uint32_t j) const {
  const T u = (T(2 * i + 1) / T(cells_)) - T(1), v = (T(2 * j + 1) / T(cells_)) - T(1);
  return faceDirection(face, u, v).normalized();
}

template <class T> const SupportStartTable<T>* supportStartTable(const std::shared_ptr<const ConvexMesh<T>>& mesh) {
  if (!mesh || mesh->vertices.size() <= kStartTableMinVertices) return nullptr;
  thread_local StartTableFront<T> front;
  typename StartTableFront<T>::Slot& slot = front.slots[StartTableFront<T>::slotOf(mesh.get())];
  if (slot.key == mesh.get() && !slot.mesh.expired()) return slot.table;
  slot.table = StartTableRegistry<T>::instance().find(mesh);
  slot.key = mesh.get();
  slot.mesh = mesh;
  return slot.table;
}

template class SupportStartTable<float>;
template class SupportStartTable<double>;
template const SupportStartTable<float>* supportStartTable<float>(const std::shared_ptr<const ConvexMesh<float>>&);
template const SupportStartTable<double>* supportStartTable<double>(const std::shared_ptr<const ConvexMesh<double>>&);

}  // namespace gq::kernels
