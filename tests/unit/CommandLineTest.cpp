#include <gtest/gtest.h>

#include "app/CommandLine.hpp"
#include "core/Errors.hpp"

namespace efg {
namespace {

TEST(CommandLine, Commands) {
  auto cl = parse_command_line({"run", "a.yaml", "-o", "out"});
  EXPECT_EQ(cl.command, "run");
  EXPECT_EQ(cl.scene, "a.yaml");
  EXPECT_EQ(cl.output_dir, "out");
  EXPECT_EQ(parse_command_line({"run", "a.yaml"}).output_dir, ".");
  EXPECT_EQ(parse_command_line({"check", "a.yaml"}).command, "check");
  cl = parse_command_line({"mesh", "a.yaml", "m.exo"});
  EXPECT_EQ(cl.mesh_output, "m.exo");
  EXPECT_EQ(parse_command_line({"--help"}).command, "help");
  EXPECT_EQ(parse_command_line({"--version"}).command, "version");
  EXPECT_EQ(parse_command_line({"schema"}).command, "schema");
  cl = parse_command_line({"study", "a.yaml", "--levels", "3", "--factor", "1.5", "--sweep", "parts.0.section.basis=linear,quadratic"});
  EXPECT_EQ(cl.levels, 3);
  EXPECT_DOUBLE_EQ(cl.factor, 1.5);
  ASSERT_EQ(cl.sweeps.size(), 1u);
}

TEST(CommandLine, Mistakes) {
  EXPECT_THROW(parse_command_line({}), InputError);
  EXPECT_THROW(parse_command_line({"rnu", "a.yaml"}), InputError);
  EXPECT_THROW(parse_command_line({"run"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "b.yaml"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "-o"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--fast"}), InputError);
  EXPECT_THROW(parse_command_line({"check", "a.yaml", "-o", "x"}), InputError);
  EXPECT_THROW(parse_command_line({"mesh", "a.yaml"}), InputError);
  EXPECT_THROW(parse_command_line({"study", "a.yaml", "--levels", "many"}), InputError);
  EXPECT_THROW(parse_command_line({"study", "a.yaml", "--sweep", "basis"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--levels", "3"}), InputError);
}

TEST(CommandLine, HelpDocumentsExitCodes) {
  const auto help = help_text();
  for (const char* code : {"0  success", "1  any other", "2  bad input", "3  numerical", "4  the run completed"})
    EXPECT_NE(help.find(code), std::string::npos) << code;
}

}  // namespace
}  // namespace efg
