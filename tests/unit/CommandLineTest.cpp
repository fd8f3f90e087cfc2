#include <gtest/gtest.h>

#include "app/CommandLine.hpp"
#include "core/Errors.hpp"
#include "core/Threads.hpp"

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
  cl = parse_command_line({"study", "a.yaml", "--levels", "3", "--factor", "1.5", "--sweep",
                           "parts.0.section.basis=linear,quadratic"});
  EXPECT_EQ(cl.levels, 3);
  EXPECT_DOUBLE_EQ(cl.factor, 1.5);
  ASSERT_EQ(cl.sweeps.size(), 1u);
  EXPECT_EQ(parse_command_line({"run", "a.yaml"}).threads, 0);
  EXPECT_EQ(parse_command_line({"run", "a.yaml", "--threads", "2"}).threads, 2);
  EXPECT_EQ(parse_command_line({"study", "a.yaml", "--threads=4"}).threads, 4);
}

TEST(CommandLine, ThreadsOptionSeenBeforeKokkosStarts) {
  std::string a0 = "efg", a1 = "run", a2 = "x.yaml", a3 = "--threads", a4 = "3", a5 = "--threads=5",
              bad = "two";
  char* plain[] = {a0.data(), a1.data(), a2.data()};
  char* spaced[] = {a0.data(), a1.data(), a2.data(), a3.data(), a4.data()};
  char* joined[] = {a0.data(), a1.data(), a5.data()};
  char* wrong[] = {a0.data(), a1.data(), a3.data(), bad.data()};
  char* dangling[] = {a0.data(), a1.data(), a3.data()};
  EXPECT_EQ(threads_option(3, plain), 0);
  EXPECT_EQ(threads_option(5, spaced), 3);
  EXPECT_EQ(threads_option(3, joined), 5);
  EXPECT_EQ(threads_option(4, wrong), 0);
  EXPECT_EQ(threads_option(3, dangling), 0);
}

TEST(CommandLine, Mistakes) {
  EXPECT_THROW(parse_command_line({}), InputError);
  EXPECT_THROW(parse_command_line({"rnu", "a.yaml"}), InputError);
  EXPECT_THROW(parse_command_line({"run"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "b.yaml"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "-o"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--fast"}), InputError);
  EXPECT_THROW(parse_command_line({"mesh", "a.yaml", "b.exo", "-o", "x"}), InputError);
  EXPECT_THROW(parse_command_line({"mesh", "a.yaml"}), InputError);
  EXPECT_THROW(parse_command_line({"study", "a.yaml", "--levels", "many"}), InputError);
  EXPECT_THROW(parse_command_line({"study", "a.yaml", "--sweep", "basis"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--levels", "3"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--threads"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--threads", "0"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--threads", "2x"}), InputError);
  EXPECT_THROW(parse_command_line({"run", "a.yaml", "--threads=-1"}), InputError);
  EXPECT_THROW(parse_command_line({"schema", "--threads", "2"}), InputError);
}

TEST(CommandLine, HelpDocumentsExitCodes) {
  const auto help = help_text();
  for (const char* code :
       {"0  success", "1  any other", "2  bad input", "3  numerical", "4  the run completed"})
    EXPECT_NE(help.find(code), std::string::npos) << code;
}

}  // namespace
}  // namespace efg
