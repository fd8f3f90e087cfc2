#include "scene/SceneMeshChecks.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/Errors.hpp"
#include "scene/ContactInput.hpp"
#include "scene/ExpressionChecks.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/ShellChecks.hpp"
#include "scene/Suggest.hpp"

namespace efg {
namespace {

template <class Set>
std::vector<std::string> names_of(const std::vector<Set>& sets) {
  std::vector<std::string> names;
  for (const auto& s : sets) names.push_back(s.name);
  return names;
}

class Checker {
 public:
  Checker(const Scene& s, const BackgroundMesh& m, const MeshOwners& owners)
      : s_(s), m_(m), owners_(owners) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& path,
                         const std::string& message) const {
    throw InputError(schema::located_message(s_.file, at, path, message));
  }

  void require_name(const YAML::Node& at, const std::string& path, const std::string& name,
                    const char* what, const std::vector<std::string>& available) const {
    for (const auto& a : available)
      if (a == name) return;
    std::string list;
    for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
    std::string message = "the mesh has no " + std::string(what) + " named '" + name + "'";
    if (auto guess = closest_match(name, available)) message += " (did you mean '" + *guess + "'?)";
    message += "; it has: " + (list.empty() ? std::string("none") : list);
    fail(at, path, message);
  }

  void require_dimension(const YAML::Node& at, const std::string& path, std::size_t size) const {
    if (size != static_cast<std::size_t>(m_.dimension))
      fail(at, path,
           "expected " + std::to_string(m_.dimension) + " entries for this " +
               std::to_string(m_.dimension) + "D mesh, found " + std::to_string(size));
  }

  void run() const {
    const auto& d = s_.document;
    const auto blocks = names_of(m_.blocks), node_sets = names_of(m_.node_sets),
               side_sets = names_of(m_.side_sets);
    std::map<std::string, std::string> block_owner;
    for (std::size_t p = 0; p < s_.parts.size(); ++p) {
      const std::string path = "parts[" + std::to_string(p) + "]";
      for (std::size_t b = 0; b < s_.parts[p].blocks.size(); ++b) {
        const auto& name = s_.parts[p].blocks[b];
        const auto at = d["parts"][p]["blocks"].IsSequence() ? d["parts"][p]["blocks"][b]
                                                             : d["parts"][p]["blocks"];
        const auto bpath = path + ".blocks[" + std::to_string(b) + "]";
        require_name(at, bpath, name, "element block", blocks);
        auto [it, inserted] = block_owner.emplace(name, s_.parts[p].name);
        if (!inserted)
          fail(at, bpath,
               "block '" + name + "' already belongs to part '" + it->second +
                   "'; a block belongs to one part");
      }
      if (m_.dimension == 2 && s_.parts[p].plane_stress &&
          s_.find_material(s_.parts[p].material)->model == "neo_hookean")
        fail(d["parts"][p]["plane"], path + ".plane",
             "plane stress is available for small-strain materials only; expected plane: strain "
             "with model neo_hookean");
      if (m_.dimension == 2 && s_.parts[p].plane_stress &&
          s_.parts[p].formulation == PartFormulation::mixed_up)
        fail(d["parts"][p]["plane"], path + ".plane",
             "a plane-stress part has no incompressibility constraint to relax: expected plane: "
             "strain with formulation mixed_up, or formulation: displacement");
      const auto& dil = s_.parts[p].section.dilation;
      if (dil.size() > 1)
        require_dimension(d["parts"][p]["section"]["dilation"], path + ".section.dilation",
                          dil.size());
    }
    // Every block's nodes become particles: a block of no part would leave them without mass
    // (the run stopped at its first step with "lumped mass 0").
    for (const auto& block : m_.blocks)
      if (!block_owner.count(block.name))
        fail(d["parts"], "parts",
             "element block '" + block.name +
                 "' of the mesh belongs to no part (its nodes would "
                 "be particles without mass); expected it in the blocks of a part");
    for (std::size_t i = 0; i < s_.boundary_conditions.size(); ++i) {
      const auto& bc = s_.boundary_conditions[i];
      const auto path = "boundary_conditions[" + std::to_string(i) + "]";
      require_name(d["boundary_conditions"][i]["node_set"], path + ".node_set", bc.node_set,
                   "node set", node_sets);
      require_nodes(d["boundary_conditions"][i]["node_set"], path + ".node_set", bc.node_set);
      if (m_.dimension == 2 && !s_.has_shells() && (bc.components[2] || bc.from_exact[2]))
        fail(bc.components[2] ? d["boundary_conditions"][i]["z"]
                              : d["boundary_conditions"][i]["from_exact_solution"],
             path, "a z component in a 2D mesh; expected x and y only");
    }
    for (std::size_t i = 0; i < s_.loads.size(); ++i) {
      const auto& load = s_.loads[i];
      const auto path = "loads[" + std::to_string(i) + "]";
      const auto& ld = d["loads"][i];
      if (load.type == "traction" || load.type == "pressure")
        require_name(ld["side_set"], path + ".side_set", load.set, "side set", side_sets);
      if (load.type == "nodal_force" || load.type == "shell_edge_load") {
        require_name(ld["node_set"], path + ".node_set", load.set, "node set", node_sets);
        require_nodes(ld["node_set"], path + ".node_set", load.set);
      }
      if (load.type != "pressure" && load.type != "shell_pressure" &&
          load.type != "shell_edge_load" && load.type != "shell_point_load" && !load.from_exact)
        require_dimension(ld["value"], path + ".value", load.value.size());
    }
    for (std::size_t i = 0; i < s_.rigid_walls.size(); ++i) {
      const auto& w = s_.rigid_walls[i];
      const auto path = "rigid_walls[" + std::to_string(i) + "]";
      const auto& wd = d["rigid_walls"][i];
      require_dimension(wd["point"], path + ".point", w.point.size());
      require_dimension(wd["normal"], path + ".normal", w.normal.size());
      double n2 = 0;
      for (double v : w.normal) n2 += v * v;
      if (!(n2 > 0)) fail(wd["normal"], path + ".normal", "expected a nonzero normal");
      if (!w.node_set.empty())
        require_name(wd["node_set"], path + ".node_set", w.node_set, "node set", node_sets);
    }
    check_rigid_bodies();
    on_this_rank([&] { check_conflicting_conditions(); });
    on_this_rank([&] { check_parts_do_not_share_nodes(); });
    check_no_far_nodes();
    check_parts_held();
    for (std::size_t i = 0; i < s_.output.history_node_sets.size(); ++i)
      require_name(d["output"]["history_node_sets"][i],
                   "output.history_node_sets[" + std::to_string(i) + "]",
                   s_.output.history_node_sets[i], "node set", node_sets);
    for (std::size_t i = 0; i < s_.initial_conditions.size(); ++i) {
      const auto path = "initial_conditions[" + std::to_string(i) + "]";
      const auto& ic = d["initial_conditions"][i];
      require_name(ic["node_set"], path + ".node_set", s_.initial_conditions[i].node_set,
                   "node set", node_sets);
      require_nodes(ic["node_set"], path + ".node_set", s_.initial_conditions[i].node_set);
      require_dimension(ic["value"], path + ".value", s_.initial_conditions[i].value.size());
    }
    for (std::size_t i = 0; i < s_.probes.size(); ++i)
      if (m_.surface.empty() || d["probes"][i]["point"].size() != 3)  // 3D: on a surface chart
        require_dimension(d["probes"][i]["point"], "probes[" + std::to_string(i) + "].point",
                          d["probes"][i]["point"].size());
    if (s_.user_solution) {
      const auto& u = d["verification"]["user_solution"];
      require_dimension(u["displacement"], "verification.user_solution.displacement",
                        s_.user_solution->displacement.size());
      if (!s_.user_solution->body_force.empty())
        require_dimension(u["body_force"], "verification.user_solution.body_force",
                          s_.user_solution->body_force.size());
    }
    check_expressions_at_nodes(s_, m_);
    if (deferred_) throw InputError(*deferred_);
  }

 private:
  bool distributed() const { return owners_.owner != nullptr; }
  bool owned(std::size_t n) const { return !distributed() || (*owners_.owner)[n] == owners_.rank; }
  void reduce_over_ranks(double* values, int count, Teuchos::EReductionType how) const {
    if (!distributed()) return;
    std::vector<double> mine(values, values + count);
    Teuchos::reduceAll(*owners_.comm, how, count, mine.data(), values);
  }

  // A check on data of this rank alone: on a rank's part of a mesh its failure waits until the
  // collective checks are done (every rank must reach them), then is thrown.
  template <class Check>
  void on_this_rank(Check check) const {
    if (!distributed()) return check();
    try {
      check();
    } catch (const InputError& e) {
      if (!deferred_) deferred_ = e.what();
    }
  }
  // An implicit stage needs every part held against rigid-body motion by its displacement
  // conditions, or its stiffness is singular (a consistent load then "solves" with an arbitrary
  // rigid motion, an inconsistent one fails in the linear solver). The test: the rigid-body
  // modes (translations, rotations about the part's centroid, coordinates scaled by its size)
  // restricted to the constrained (node, component) pairs must have full rank.
  // Each implicit stage with the conditions active in it (a springback stage keeps only those
  // that stop the rigid-body motion).
  void check_parts_held() const {
    for (std::size_t i = 0; i < s_.stages.size(); ++i) {
      if (s_.stages[i].driver != "implicit") continue;
      for (std::size_t p = 0; p < s_.parts.size(); ++p) {
        const auto free = free_rigid_motion(p, s_.stages[i].name);
        if (free.empty()) continue;
        fail(s_.document["stages"][i]["driver"], "stages[" + std::to_string(i) + "].driver",
             "an implicit (static) stage needs part '" + s_.parts[p].name +
                 "' held against rigid-body motion, but the displacement conditions active in "
                 "stage '" +
                 s_.stages[i].name + "' leave it free to " + free +
                 " (its stiffness is singular); add displacement conditions that stop it, or "
                 "use driver: explicit");
      }
    }
  }

  // Rigid bodies: every point and vector with the mesh's dimension; a 3D cylinder's axis; a
  // mass from density only for a shape with a volume.
  void check_rigid_bodies() const {
    // shells live in 3D whatever their mesh (their chart is 2D): bodies are given in 3D
    const std::size_t space = s_.has_shells() ? 3 : static_cast<std::size_t>(m_.dimension);
    for (std::size_t i = 0; i < s_.rigid_bodies.size(); ++i) {
      const auto& b = s_.rigid_bodies[i];
      const auto path = "rigid_bodies[" + std::to_string(i) + "]";
      const auto& bd = s_.document["rigid_bodies"][i];
      const std::pair<const char*, const std::vector<double>*> vectors[] = {
          {"point", &b.point}, {"normal", &b.normal}, {"center", &b.center},
          {"lower", &b.lower}, {"upper", &b.upper},   {"velocity", &b.velocity}};
      for (const auto& [key, v] : vectors) {
        if (v->empty()) continue;
        if (!s_.has_shells()) require_dimension(bd[key], path + "." + key, v->size());
        if (s_.has_shells() && v->size() != 3)
          fail(
              bd[key], path + "." + key,
              "expected 3 entries (shells touch bodies in 3D), found " + std::to_string(v->size()));
      }
      if (b.shape == "mesh" && !b.angular_velocity.empty() &&
          b.angular_velocity.size() != (space == 2 ? 1u : 3u))
        fail(
            bd["angular_velocity"], path + ".angular_velocity",
            "expected " +
                std::string(space == 2 ? "1 entry (about z in 2D)" : "3 entries (a vector in 3D)") +
                ", found " + std::to_string(b.angular_velocity.size()));
      if (b.shape == "cylinder" && space == 3 && b.axis.empty())
        fail(bd, path, "a cylinder in a 3D model needs axis");
      if (b.density > 0 && !(rigid_body_volume(b, static_cast<int>(space)) > 0))
        fail(bd["density"], path + ".density",
             "a " + b.shape + (b.shape == "cylinder" ? " (infinite along its axis)" : "") +
                 " has no finite volume to take a mass from density; give mass");
    }
  }

  // A node far from the rest of its part (x = 1e6 in a part 10 long: a mistyped coordinate)
  // stretches its cells by orders of magnitude; later checks then fail for reasons that hide it
  // (a held part "free to rotate", an ill-conditioned moment matrix). Found first: a cell whose
  // diameter exceeds kStretch times the part's typical one (the geometric mean, which one
  // outlier barely moves; graded meshes stay within a few hundred of it).
  void check_no_far_nodes() const {
    constexpr double kStretch = 1e4;
    const auto udim = static_cast<std::size_t>(m_.dimension);
    const auto distance = [&](LocalIndex a, LocalIndex b) {
      double d2 = 0;
      for (std::size_t k = 0; k < udim; ++k) {
        const double d = m_.coordinates[static_cast<std::size_t>(a) * udim + k] -
                         m_.coordinates[static_cast<std::size_t>(b) * udim + k];
        d2 += d * d;
      }
      return std::sqrt(d2);
    };
    for (std::size_t p = 0; p < s_.parts.size(); ++p) {
      // Each cell once (by the owner of its first node), its diameter over its node pairs.
      const auto for_each_cell = [&](auto&& f) {
        for (const auto& b : m_.blocks) {
          const auto& names = s_.parts[p].blocks;
          if (std::find(names.begin(), names.end(), b.name) == names.end()) continue;
          const auto n = static_cast<std::size_t>(cell_node_count(b.type));
          for (std::size_t c = 0; c < b.cell_count(); ++c) {
            const auto* k = &b.connectivity[c * n];
            if (!owned(static_cast<std::size_t>(k[0]))) continue;
            double diameter = 0;
            for (std::size_t i = 0; i < n; ++i)
              for (std::size_t j = i + 1; j < n; ++j)
                diameter = std::max(diameter, distance(k[i], k[j]));
            f(b, c, k, n, diameter);
          }
        }
      };
      double sums[2] = {0, 0};  // sum of log diameters, count
      for_each_cell(
          [&](const ElementBlock&, std::size_t, const LocalIndex*, std::size_t, double d) {
            if (d > 0) {
              sums[0] += std::log(d);
              sums[1] += 1;
            }
          });
      reduce_over_ranks(sums, 2, Teuchos::REDUCE_SUM);
      if (sums[1] == 0) continue;
      const double typical = std::exp(sums[0] / sums[1]);
      on_this_rank([&] {
        for_each_cell([&](const ElementBlock& b, std::size_t c, const LocalIndex* k, std::size_t n,
                          double d) {
          if (!(d > kStretch * typical)) return;
          std::size_t far = 0;  // the node farthest from the others
          double most = -1;
          for (std::size_t i = 0; i < n; ++i) {
            double sum = 0;
            for (std::size_t j = 0; j < n; ++j) sum += distance(k[i], k[j]);
            if (sum > most) most = sum, far = i;
          }
          const auto node = static_cast<std::size_t>(k[far]);
          std::ostringstream o;
          o.precision(6);
          o << "part '" << s_.parts[p].name << "': mesh node " << m_.global_node(node) + 1
            << " at (";
          for (std::size_t i = 0; i < udim; ++i)
            o << (i ? ", " : "") << m_.coordinates[node * udim + i];
          o.precision(3);
          o << ") lies far from the rest of the part: it stretches cell " << c + 1 << " of block '"
            << b.name << "' to " << d << " across, " << d / typical
            << " times the part's typical cell size " << typical
            << "; expected cells of comparable size (a mistyped coordinate?)";
          fail(s_.document["parts"][p]["blocks"], "parts[" + std::to_string(p) + "].blocks",
               o.str());
        });
      });
    }
  }

  // "" when part p is held; otherwise the free motion in words.
  // The modes are centred and scaled on the constrained nodes, not on the whole part: the rank
  // does not depend on the centre, and a node far from the supports (x = 1e6 in a part 10 long)
  // would otherwise shrink the rotations at the supports below the rank test's tolerance and
  // report a held part free to rotate (issue 55).
  std::string free_rigid_motion(std::size_t p, const std::string& stage) const {
    const int dim = m_.dimension;
    const auto udim = static_cast<std::size_t>(dim);
    std::vector<char> in_part(m_.node_count(), 0);
    for (const auto& b : m_.blocks)
      if (std::find(s_.parts[p].blocks.begin(), s_.parts[p].blocks.end(), b.name) !=
          s_.parts[p].blocks.end())
        for (auto n : b.connectivity) in_part[static_cast<std::size_t>(n)] = 1;
    std::vector<char> constrained(m_.node_count() * udim, 0);
    for (const auto& bc : s_.boundary_conditions) {
      if (bc.type != "displacement" || !bc.stages.includes(stage)) continue;
      for (auto n : m_.find_node_set(bc.node_set)->nodes)
        for (std::size_t c = 0; c < udim; ++c)
          if (bc.components[c] || bc.from_exact[c])
            constrained[static_cast<std::size_t>(n) * udim + c] = 1;
    }
    const auto held = [&](std::size_t n) {
      return std::any_of(&constrained[n * udim], &constrained[n * udim] + udim,
                         [](char c) { return c != 0; });
    };
    double centre[3] = {0, 0, 0}, lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    double count = 0, part_count = 0;
    for (std::size_t n = 0; n < m_.node_count(); ++n) {
      if (!in_part[n] || !owned(n)) continue;
      part_count += 1;
      if (!held(n)) continue;
      count += 1;
      for (std::size_t k = 0; k < udim; ++k) {
        const double x = m_.coordinates[n * udim + k];
        centre[k] += x;
        lo[k] = std::min(lo[k], x);
        hi[k] = std::max(hi[k], x);
      }
    }
    reduce_over_ranks(centre, 3, Teuchos::REDUCE_SUM);
    reduce_over_ranks(&count, 1, Teuchos::REDUCE_SUM);
    reduce_over_ranks(&part_count, 1, Teuchos::REDUCE_SUM);
    reduce_over_ranks(lo, 3, Teuchos::REDUCE_MIN);
    reduce_over_ranks(hi, 3, Teuchos::REDUCE_MAX);
    if (part_count == 0) return "";
    double size = 0;
    for (std::size_t k = 0; k < udim && count > 0; ++k) {
      centre[k] /= count;
      size = std::max(size, hi[k] - lo[k]);
    }
    if (!(size > 0)) size = 1;  // one held point (or none): rotations are free either way
    // Gram matrix of the modes over the constrained pairs: modes are 2 translations + 1 rotation
    // in 2D, 3 + 3 in 3D; u_rot = omega x r with r the scaled position.
    const int modes = dim == 2 ? 3 : 6;
    std::vector<double> gram(static_cast<std::size_t>(modes * modes), 0.0);
    for (std::size_t n = 0; n < m_.node_count(); ++n) {
      if (!in_part[n] || !owned(n) || !held(n)) continue;
      double r[3] = {0, 0, 0};
      for (std::size_t k = 0; k < udim; ++k)
        r[k] = (m_.coordinates[n * udim + k] - centre[k]) / size;
      for (std::size_t c = 0; c < udim; ++c) {
        if (!constrained[n * udim + c]) continue;
        double row[6] = {0, 0, 0, 0, 0, 0};
        row[c] = 1.0;
        if (dim == 2) {
          row[2] = c == 0 ? -r[1] : r[0];  // omega_z x r
        } else {
          // (omega x r)_c for omega = e_x, e_y, e_z
          const double rot[3][3] = {{0, r[2], -r[1]}, {-r[2], 0, r[0]}, {r[1], -r[0], 0}};
          for (int w = 0; w < 3; ++w) row[3 + w] = rot[c][w];
        }
        for (int a = 0; a < modes; ++a)
          for (int b = 0; b < modes; ++b)
            gram[static_cast<std::size_t>(a * modes + b)] += row[a] * row[b];
      }
    }
    reduce_over_ranks(gram.data(), modes * modes, Teuchos::REDUCE_SUM);
    std::vector<double> eig(static_cast<std::size_t>(modes)),
        work(static_cast<std::size_t>(4 * modes));
    int info = 0;
    Teuchos::LAPACK<int, double>().SYEV('V', 'U', modes, gram.data(), modes, eig.data(),
                                        work.data(), 4 * modes, &info);
    // Eigenvalues ascending; a held part has every mode constrained by at least one pair of
    // order-one weight, so the smallest is far from 0 (0 up to round-off when free).
    if (info != 0 || eig[0] > 1e-10 * std::max(1.0, eig.back())) return "";
    const double* v = gram.data();  // first eigenvector: the free motion
    std::ostringstream o;
    o.precision(2);
    const double rotation =
        dim == 2 ? std::abs(v[2]) : std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
    if (rotation < 1e-6) {
      o << "translate along (";
      for (int k = 0; k < dim; ++k) o << (k ? ", " : "") << (std::abs(v[k]) < 1e-12 ? 0.0 : v[k]);
      o << ")";
    } else {
      o << (dim == 2 ? "rotate in its plane" : "rotate") << " (and possibly translate)";
    }
    return o.str();
  }

  // Each part discretizes its own particles (its own shape functions); a node in two parts would
  // be one dof with two unrelated, non-interpolating approximations around it, so a bonded
  // multi-material interface is not supported yet: say so where the second part names the block.
  void check_parts_do_not_share_nodes() const {
    std::vector<int> part_of(m_.node_count(), -1);
    for (std::size_t p = 0; p < s_.parts.size(); ++p)
      for (std::size_t b = 0; b < s_.parts[p].blocks.size(); ++b) {
        const auto& block = *std::find_if(m_.blocks.begin(), m_.blocks.end(), [&](const auto& x) {
          return x.name == s_.parts[p].blocks[b];
        });
        for (auto node : block.connectivity) {
          auto& owner = part_of[static_cast<std::size_t>(node)];
          if (owner >= 0 && owner != static_cast<int>(p)) {
            const auto& blocks = s_.document["parts"][p]["blocks"];
            fail(blocks.IsSequence() ? blocks[b] : blocks,
                 "parts[" + std::to_string(p) + "].blocks[" + std::to_string(b) + "]",
                 "part '" + s_.parts[p].name + "' shares mesh node " +
                     std::to_string(m_.global_node(static_cast<std::size_t>(node)) + 1) +
                     " with part '" + s_.parts[static_cast<std::size_t>(owner)].name +
                     "'; bonded parts that share nodes are not supported yet: expected each "
                     "part to have its own nodes (or put both blocks in one part of one "
                     "material)");
          }
          owner = static_cast<int>(p);
        }
      }
  }

  // A condition, load or initial value on an empty set would silently do nothing.
  void require_nodes(const YAML::Node& at, const std::string& path, const std::string& name) const {
    const auto* set = m_.find_node_set(name);
    if (!set) return;
    double count = 0;
    for (auto n : set->nodes) count += owned(static_cast<std::size_t>(n)) ? 1 : 0;
    reduce_over_ranks(&count, 1, Teuchos::REDUCE_SUM);
    if (count == 0) fail(at, path, "node set '" + name + "' is empty; expected a set with nodes");
  }

  static bool same_prescription(const BoundaryConditionSpec& a, const BoundaryConditionSpec& b,
                                std::size_t c) {
    const auto& u = a.components[c];
    const auto& v = b.components[c];
    const bool same_value = u.has_value() == v.has_value() && (!u || u->same_as(*v));
    return a.type == b.type && same_value && a.from_exact[c] == b.from_exact[c] &&
           a.curve == b.curve;
  }

  // Two conditions prescribing one dof differently: one of them would silently win.
  void check_conflicting_conditions() const {
    const auto& bcs = s_.boundary_conditions;
    const auto dim = static_cast<std::size_t>(m_.dimension);
    for (std::size_t j = 0; j < bcs.size(); ++j)
      for (std::size_t i = 0; i < j; ++i)
        for (std::size_t c = 0; c < dim; ++c) {
          const bool both = (bcs[i].components[c] || bcs[i].from_exact[c]) &&
                            (bcs[j].components[c] || bcs[j].from_exact[c]);
          if (!both || same_prescription(bcs[i], bcs[j], c) ||
              !share_a_stage(bcs[i].stages, bcs[j].stages))
            continue;
          const auto shared = first_shared_node(bcs[i].node_set, bcs[j].node_set);
          if (shared < 0) continue;
          const char axis = static_cast<char>('x' + c);
          fail(s_.document["boundary_conditions"][j],
               "boundary_conditions[" + std::to_string(j) + "]",
               "condition '" + bcs[j].name + "' and condition '" + bcs[i].name +
                   "' prescribe component " + axis + " of node " +
                   std::to_string(m_.global_node(static_cast<std::size_t>(shared)) + 1) +
                   " differently (node sets '" + bcs[j].node_set + "' and '" + bcs[i].node_set +
                   "' share it); expected one prescription per component of a node");
        }
  }

  // Two stage lists that meet: the conditions act together somewhere (a scene without stages
  // runs none, but its conditions must still agree).
  bool share_a_stage(const ActiveStages& a, const ActiveStages& b) const {
    if (a.names.empty() || b.names.empty()) return true;
    for (const auto& n : a.names)
      if (b.includes(n)) return true;
    return false;
  }

  LocalIndex first_shared_node(const std::string& a, const std::string& b) const {
    const auto* sa = m_.find_node_set(a);
    const auto* sb = m_.find_node_set(b);
    std::vector<char> in(m_.node_count(), 0);
    for (auto n : sa->nodes) in[static_cast<std::size_t>(n)] = 1;
    LocalIndex first = -1;
    for (auto n : sb->nodes)
      if (in[static_cast<std::size_t>(n)] && (first < 0 || n < first)) first = n;
    return first;
  }

  const Scene& s_;
  const BackgroundMesh& m_;
  MeshOwners owners_;
  mutable std::optional<std::string> deferred_;
};

}  // namespace

void check_scene_against_mesh(const Scene& scene, const BackgroundMesh& mesh,
                              const MeshOwners& owners) {
  check_shell_scene(scene, mesh);
  Checker(scene, mesh, owners).run();
}

}  // namespace efg
