#include <gtest/gtest.h>

#include <cmath>

#include <exodusII.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/Errors.hpp"
#include "io/ExodusReader.hpp"
#include "io/ExodusWriter.hpp"
#include "io/NetcdfHeaderCheck.hpp"
#include "mesh/MeshValidation.hpp"
#include "mesh/SurfaceChart.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

void expect_same_mesh(const BackgroundMesh& a, const BackgroundMesh& b) {
  EXPECT_EQ(a.dimension, b.dimension);
  EXPECT_EQ(a.coordinates, b.coordinates);  // bitwise: doubles are stored as doubles
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].name, b.blocks[i].name);
    EXPECT_EQ(a.blocks[i].id, b.blocks[i].id);
    EXPECT_EQ(a.blocks[i].type, b.blocks[i].type);
    EXPECT_EQ(a.blocks[i].connectivity, b.blocks[i].connectivity);
  }
  ASSERT_EQ(a.node_sets.size(), b.node_sets.size());
  for (std::size_t i = 0; i < a.node_sets.size(); ++i) {
    EXPECT_EQ(a.node_sets[i].name, b.node_sets[i].name);
    EXPECT_EQ(a.node_sets[i].id, b.node_sets[i].id);
    EXPECT_EQ(a.node_sets[i].nodes, b.node_sets[i].nodes);
  }
  ASSERT_EQ(a.side_sets.size(), b.side_sets.size());
  for (std::size_t i = 0; i < a.side_sets.size(); ++i) {
    EXPECT_EQ(a.side_sets[i].name, b.side_sets[i].name);
    EXPECT_EQ(a.side_sets[i].cells, b.side_sets[i].cells);
    EXPECT_EQ(a.side_sets[i].sides, b.side_sets[i].sides);
  }
}

class RoundTrip : public ::testing::TestWithParam<CellType> {};

TEST_P(RoundTrip, MeshAndEveryFieldComeBackEqual) {
  const auto mesh = generate_mesh(test::box_spec(GetParam(), 2, 0.25));
  const auto path = test::scratch_dir("roundtrip") + "/" + cell_scene_name(GetParam()) + ".e";
  std::filesystem::remove(path);
  OutputLayout layout;
  layout.nodal = vector_component_names("displacement", mesh.dimension);
  layout.nodal.push_back("nodal_volume");
  layout.element = {"cell_value"};
  layout.global = {"kinetic_energy", "internal_energy"};
  std::vector<std::vector<std::vector<double>>> nodal_records;
  std::vector<std::vector<double>> element_records, global_records;
  {
    ExodusWriter writer(path, mesh, layout, "round trip");
    EXPECT_TRUE(std::filesystem::exists(path + ".part"));
    EXPECT_FALSE(std::filesystem::exists(path));  // the final name appears only on close
    for (int step = 0; step < 3; ++step) {
      std::vector<std::vector<double>> nodal(layout.nodal.size(),
                                             std::vector<double>(mesh.node_count()));
      for (std::size_t v = 0; v < nodal.size(); ++v)
        for (std::size_t n = 0; n < mesh.node_count(); ++n)
          nodal[v][n] =
              1.0 / 3.0 * static_cast<double>(n) + 0.1 * static_cast<double>(v) - step * 1e-7;
      std::vector<double> element(mesh.cell_count());
      for (std::size_t c = 0; c < element.size(); ++c)
        element[c] = std::sqrt(2.0) * static_cast<double>(c + step);
      const std::vector<double> global = {0.5 * step, -1.0 / 7.0 * step};
      writer.write_record(0.1 * step, nodal, {element}, global);
      nodal_records.push_back(nodal);
      element_records.push_back(element);
      global_records.push_back(global);
    }
    writer.close();
  }
  EXPECT_FALSE(std::filesystem::exists(path + ".part"));
  expect_same_mesh(mesh, read_exodus_mesh(path));
  const auto results = read_exodus_results(path);
  ASSERT_EQ(results.times.size(), 3u);
  for (std::size_t step = 0; step < 3; ++step) {
    EXPECT_EQ(results.times[step], 0.1 * static_cast<double>(step));
    for (std::size_t v = 0; v < layout.nodal.size(); ++v)
      EXPECT_EQ(results.nodal.at(layout.nodal[v])[step], nodal_records[step][v]) << layout.nodal[v];
    EXPECT_EQ(results.element.at("cell_value")[step], element_records[step]);
    EXPECT_EQ(results.global.at("kinetic_energy")[step], global_records[step][0]);
    EXPECT_EQ(results.global.at("internal_energy")[step], global_records[step][1]);
  }
}

INSTANTIATE_TEST_SUITE_P(AllElements, RoundTrip,
                         ::testing::Values(CellType::quad4, CellType::tri3, CellType::hex8,
                                           CellType::tet4, CellType::wedge6),
                         [](const auto& p) { return cell_scene_name(p.param); });

TEST(ExodusWriter, RefusesNonFiniteValues) {
  const auto mesh = generate_mesh(test::box_spec(CellType::quad4, 1));
  const auto path = test::scratch_dir("nonfinite") + "/nan.e";
  ExodusWriter writer(path, mesh, OutputLayout{{"u"}, {}, {}}, "nan");
  std::vector<double> u(mesh.node_count(), 0.0);
  u[1] = std::nan("");
  // Numerical trouble (exit 3) naming the field, the node and the time.
  try {
    writer.write_record(0.25, {u}, {}, {});
    FAIL() << "a NaN was written";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("output field 'u' at node 2, t = 0.25"), std::string::npos)
        << e.what();
  }
}

TEST(ExodusWriter, UnclosedWriterLeavesEarlierResultUntouched) {
  const auto mesh = generate_mesh(test::box_spec(CellType::quad4, 1));
  const auto path = test::scratch_dir("unclosed") + "/result.e";
  { std::ofstream(path) << "earlier result"; }
  {
    ExodusWriter writer(path, mesh, OutputLayout{{"u"}, {}, {}}, "crash");
    writer.write_record(0.0, {std::vector<double>(mesh.node_count(), 1.0)}, {}, {});
    // destroyed without close(): a run stopped by an error other than a numerical one (bad
    // input found at run time) writes nothing (issue 55)
  }
  std::ifstream in(path);
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "earlier result");
  EXPECT_FALSE(std::filesystem::exists(path + ".part"));
  {
    ExodusWriter writer(path, mesh, OutputLayout{{"u"}, {}, {}}, "crash");
    writer.write_record(0.0, {std::vector<double>(mesh.node_count(), 1.0)}, {}, {});
    writer.close(/*keep_partial=*/true);  // a numerical failure keeps the records so far
  }
  std::ifstream again(path);
  std::getline(again, text);
  EXPECT_EQ(text, "earlier result");
  // The partial file is a readable Exodus file holding the record written before the failure
  // (a killed process leaves it the same way: each record is flushed).
  EXPECT_EQ(read_exodus_results(path + ".part").times.size(), 1u);
}

std::string read_error(const std::string& path) {
  try {
    read_exodus_mesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ExodusReader, RejectsFilesThatAreNotExodus) {
  const auto dir = test::scratch_dir("corrupt");
  { std::ofstream(dir + "/text.e") << "this is not a mesh\n"; }
  EXPECT_NE(read_error(dir + "/text.e").find("cannot be opened as Exodus II"), std::string::npos);
  EXPECT_NE(read_error(dir + "/missing.e").find("cannot be opened"), std::string::npos);
}

// A truncated file must never come back as a valid mesh: either the reader or the mesh
// validation (which every run applies) rejects it.
TEST(ExodusReader, TruncatedFilesAreRejected) {
  const auto dir = test::scratch_dir("truncated");
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 3));
  {
    ExodusWriter writer(dir + "/full.e", mesh, OutputLayout{}, "full");
    writer.close();
  }
  const auto size = std::filesystem::file_size(dir + "/full.e");
  for (double fraction : {0.05, 0.3, 0.6, 0.9, 0.99}) {
    const auto cut = dir + "/cut.e";
    std::filesystem::copy_file(dir + "/full.e", cut,
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(cut,
                                 static_cast<std::uintmax_t>(fraction * static_cast<double>(size)));
    EXPECT_THROW(validate_mesh(read_exodus_mesh(cut)), InputError)
        << "kept " << fraction << " of the file";
  }
}

/// A one-block 3D file of one cell of `type` with `nodes` nodes at x, y, z.
std::string one_cell_file(const char* name, const char* type, int nodes, const double* x,
                          const double* y, const double* z) {
  const auto path = test::scratch_dir(name) + "/" + name + ".e";
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  EXPECT_GE(id, 0);
  EXPECT_GE(ex_put_init(id, name, 3, nodes, 1, 1, 0, 0), 0);
  EXPECT_GE(ex_put_coord(id, x, y, z), 0);
  EXPECT_GE(ex_put_block(id, EX_ELEM_BLOCK, 7, type, 1, nodes, 0, 0, 0), 0);
  std::vector<int> conn;
  for (int k = 1; k <= nodes; ++k) conn.push_back(k);
  EXPECT_GE(ex_put_conn(id, EX_ELEM_BLOCK, 7, conn.data(), nullptr, nullptr), 0);
  ex_close(id);
  return path;
}

TEST(ExodusReader, RejectsUnsupportedElementTypes) {
  const double x[2] = {0, 1}, y[2] = {0, 0}, z[2] = {0, 0};
  const auto error = read_error(one_cell_file("beam", "BEAM2", 2, x, y, z));
  EXPECT_NE(error.find("element type 'BEAM2'"), std::string::npos) << error;
}

// A SHELL4 cell in 3D is a shell surface: read as a quad4 of a 3D mesh, its chart (the
// projection onto the plane normal to its mean normal) keeps the lengths of a flat cell, tilted
// here by 30 degrees about x, and the 3D positions stay in BackgroundMesh::surface.
TEST(ExodusReader, ReadsShellBlocksAsSurfaceCells) {
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const double x[4] = {0, 2, 2, 0}, y[4] = {0, 0, c, c}, z[4] = {0, 0, s, s};
  auto mesh = read_exodus_mesh(one_cell_file("shell", "SHELL4", 4, x, y, z));
  ASSERT_EQ(mesh.dimension, 3);
  ASSERT_EQ(mesh.blocks.at(0).type, CellType::quad4);
  ASSERT_TRUE(is_surface_mesh(mesh));
  chart_surface_mesh(mesh);
  ASSERT_EQ(mesh.dimension, 2);
  ASSERT_EQ(mesh.surface.size(), 12u);
  EXPECT_EQ(mesh.surface[3 * 2 + 2], s);
  const auto& p = mesh.coordinates;
  const auto length = [&](int a, int b) {
    return std::hypot(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]);
  };
  EXPECT_NEAR(length(0, 1), 2.0, 1e-14);
  EXPECT_NEAR(length(1, 2), 1.0, 1e-14);
  EXPECT_NEAR(length(0, 2), std::sqrt(5.0), 1e-14);
}

// A shell block's thickness attribute (tests/scenes/shells/meshes/tapered_strip_16.exo, written
// by make_meshes.py with netCDF4: t0 (1 + x) at each cell's centre, t0 = 0.01) is read per cell,
// in the file's cell order.
TEST(ExodusReader, ReadsTheThicknessAttributeOfShellBlocks) {
  const auto mesh = read_exodus_mesh(std::string(EFG_SOURCE_DIR) +
                                     "/tests/scenes/shells/meshes/tapered_strip_16.exo");
  const auto& block = mesh.blocks.at(0);
  ASSERT_EQ(block.thickness.size(), block.cell_count());
  ASSERT_EQ(block.cell_count(), 32u);
  for (std::size_t c = 0; c < block.cell_count(); ++c) {
    double centre = 0;
    for (std::size_t k = 0; k < 4; ++k)
      centre += mesh.coordinates[3 * static_cast<std::size_t>(block.connectivity[4 * c + k])] / 4;
    EXPECT_NEAR(block.thickness[c], 0.01 * (1 + centre), 1e-15) << "cell " << c + 1;
  }
  // a block without attributes carries none
  EXPECT_TRUE(
      read_exodus_mesh(std::string(EFG_SOURCE_DIR) + "/tests/scenes/shells/meshes/roof_4.exo")
          .blocks.at(0)
          .thickness.empty());
}

// A surface folding beyond the projection chart (two cells 170 degrees apart, each 85 degrees
// from their mean normal) is refused with the cell named.
TEST(ExodusReader, ASurfaceBeyondTheProjectionChartIsRefused) {
  BackgroundMesh mesh;
  mesh.dimension = 3;
  const double a = 170.0 * M_PI / 180;  // the second cell folded back by 170 degrees
  mesh.coordinates = {0,
                      0,
                      0,
                      1,
                      0,
                      0,
                      1,
                      1,
                      0,
                      0,
                      1,
                      0,
                      0,
                      1 + std::cos(a),
                      std::sin(a),
                      1,
                      1 + std::cos(a),
                      std::sin(a)};
  mesh.blocks.push_back({"block_1", 1, CellType::quad4, {0, 1, 2, 3, 3, 2, 5, 4}, {}});
  try {
    chart_surface_mesh(mesh);
    FAIL() << "a fold was charted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 1 (block 'block_1') turns its normal by 85"),
              std::string::npos)
        << e.what();
  }
}

// A corrupted count in a classic netCDF header is refused before the library allocates what it
// claims (the input fuzzer found a flipped byte costing 36 s); the intact file passes.
TEST(ExodusReader, CorruptedHeaderCountsAreRefusedQuickly) {
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 2));
  const auto path = test::scratch_dir("corrupt") + "/box.e";
  {
    ExodusWriter writer(path, mesh, OutputLayout{}, "box");
    writer.close();
  }
  EXPECT_EQ(exodus::classic_header_problem(path), "");
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // Byte 12..15: the number of dimensions (after "CDF", version, numrecs and the list tag).
  bytes[12] = '\x7f';
  const auto bad = test::scratch_dir("corrupt") + "/bad.e";
  std::ofstream(bad, std::ios::binary) << bytes;
  EXPECT_NE(exodus::classic_header_problem(bad).find("exceeds the file"), std::string::npos);
  EXPECT_THROW(read_exodus_mesh(bad), InputError);
}

}  // namespace
}  // namespace efg
