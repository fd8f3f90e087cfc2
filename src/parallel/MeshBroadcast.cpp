#include "parallel/MeshBroadcast.hpp"

#include <cstring>
#include <stdexcept>

#include "parallel/RootBroadcast.hpp"

namespace efg {
namespace {

class Writer {
 public:
  template <class T>
  void pod(const T& v) {
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod(static_cast<std::uint64_t>(v.size()));
    const auto* p = reinterpret_cast<const char*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
  }
  void str(const std::string& s) { vec(std::vector<char>(s.begin(), s.end())); }
  std::vector<char> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<char>& b) : bytes(b) {}
  template <class T>
  T pod() {
    T v;
    take(&v, sizeof(T));
    return v;
  }
  template <class T>
  std::vector<T> vec() {
    std::vector<T> v(pod<std::uint64_t>());
    take(v.data(), v.size() * sizeof(T));
    return v;
  }
  std::string str() {
    const auto v = vec<char>();
    return std::string(v.begin(), v.end());
  }

 private:
  void take(void* out, std::size_t n) {
    if (at + n > bytes.size()) throw std::runtime_error("mesh broadcast: truncated message");
    if (n) std::memcpy(out, bytes.data() + at, n);
    at += n;
  }
  const std::vector<char>& bytes;
  std::size_t at = 0;
};

}  // namespace

std::vector<char> serialize(const BackgroundMesh& mesh) {
  Writer w;
  w.pod(mesh.dimension);
  w.str(mesh.source);
  w.vec(mesh.coordinates);
  w.vec(mesh.surface);
  w.pod(mesh.chart_plane);
  w.pod(static_cast<std::uint64_t>(mesh.blocks.size()));
  for (const auto& b : mesh.blocks) {
    w.str(b.name);
    w.pod(b.id);
    w.pod(b.type);
    w.vec(b.connectivity);
    w.vec(b.thickness);
  }
  w.pod(static_cast<std::uint64_t>(mesh.node_sets.size()));
  for (const auto& s : mesh.node_sets) {
    w.str(s.name);
    w.pod(s.id);
    w.vec(s.nodes);
  }
  w.pod(static_cast<std::uint64_t>(mesh.side_sets.size()));
  for (const auto& s : mesh.side_sets) {
    w.str(s.name);
    w.pod(s.id);
    w.vec(s.cells);
    w.vec(s.sides);
  }
  return std::move(w.bytes);
}

BackgroundMesh deserialize(const std::vector<char>& bytes) {
  Reader r(bytes);
  BackgroundMesh mesh;
  mesh.dimension = r.pod<int>();
  mesh.source = r.str();
  mesh.coordinates = r.vec<double>();
  mesh.surface = r.vec<double>();
  mesh.chart_plane = r.pod<SurfaceProjection>();
  mesh.blocks.resize(r.pod<std::uint64_t>());
  for (auto& b : mesh.blocks) {
    b.name = r.str();
    b.id = r.pod<std::int64_t>();
    b.type = r.pod<CellType>();
    b.connectivity = r.vec<LocalIndex>();
    b.thickness = r.vec<double>();
  }
  mesh.node_sets.resize(r.pod<std::uint64_t>());
  for (auto& s : mesh.node_sets) {
    s.name = r.str();
    s.id = r.pod<std::int64_t>();
    s.nodes = r.vec<LocalIndex>();
  }
  mesh.side_sets.resize(r.pod<std::uint64_t>());
  for (auto& s : mesh.side_sets) {
    s.name = r.str();
    s.id = r.pod<std::int64_t>();
    s.cells = r.vec<LocalIndex>();
    s.sides = r.vec<int>();
  }
  return mesh;
}

BackgroundMesh load_on_root_and_broadcast(const CommPtr& comm,
                                          const std::function<BackgroundMesh()>& load) {
  if (comm->getSize() == 1) return load();
  return deserialize(produce_on_root(comm, [&] { return serialize(load()); }));
}

}  // namespace efg
