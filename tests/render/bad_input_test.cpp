// Bad command lines: a one-line message naming the problem, exit code 2, and no output
// file. A good command line, for contrast, exits 0 and writes all three files; --out gets
// .exr appended when it has none, and stdout carries JSON only with --json.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

struct Run {
  int code;
  std::string err, out;
};

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  std::remove(path.c_str());
  return ss.str();
}

Run Render(const std::string& args) {
  std::string stem = "bad_input_" + std::to_string(getpid());
  std::string cmd = std::string(VRL_RENDER) + " " + args + " >" + stem + ".out 2>" + stem + ".err";
  int status = std::system(cmd.c_str());
  std::string err = Slurp(stem + ".err"), out = Slurp(stem + ".out");
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err, out};
}

bool Exists(const std::string& p) { return std::ifstream(p).good(); }

}  // namespace

TEST_CASE("bad input exits with code 2, one line, and writes nothing", "[render][cli]") {
  const std::string out = "bad_input_out";
  const std::string base = "--quiet --width 8 --height 8 --spp 1 --vrls 2 --out " + out + ".exr ";
  const std::string base_no_out = "--quiet --width 8 --height 8 --spp 1 --vrls 2 ";
  struct Case {
    std::string args, word;
  };
  const Case cases[] = {
      {"--scene nowhere", "unknown scene"},
      {"--scene cube --sampler magic", "unknown sampler"},
      {"--scene cube --g 1", "--g"},
      {"--scene cube --g -1.5", "--g"},
      {"--scene cube --g nan", "--g"},
      {"--scene cube --sigma-s -0.1", "--sigma-s"},
      {"--scene cube --sigma-a -1", "--sigma-a"},
      {"--scene cube --sigma-s 3e38 --sigma-a 3e38", "--sigma-s + --sigma-a"},
      {"--scene cube --width 0", "--width"},
      {"--scene cube --height -4", "--height"},
      {"--scene cube --spp 0", "--spp"},
      {"--scene cube --time 0", "--time"},
      {"--scene cube --time -2", "--time"},
      {"--scene cube --vrls 0", "--vrls"},
      {"--scene cube --vpl-bound nan", "--vpl-bound"},
      {"--scene cube --vrl-bound nan", "--vrl-bound"},
      {"--scene cube --pixel-samples sobol", "--pixel-samples"},
      {"--scene cube --reference /nonexistent-dir/ref.exr", "cannot read reference"},
      {"--scene cube --no-such-option", "no-such-option"},
      {"--scene bidirectional --gather m2s", "no surfaces"},
      {"", "--scene"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    Run r = Render(base + c.args);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.word) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(Exists(out + ".exr"));
    CHECK_FALSE(Exists(out + ".png"));
    CHECK_FALSE(Exists(out + ".json"));
  }
  Run unwritable = Render(base_no_out + "--scene cube --out /nonexistent-dir/x.exr");
  CHECK(unwritable.code == 2);
  CHECK(unwritable.err.find("cannot write output file") != std::string::npos);
  CHECK_FALSE(Exists("/nonexistent-dir/x.exr"));
  Run png = Render(base_no_out + "--scene cube --out " + out + ".png");
  CHECK(png.code == 2);
  CHECK(png.err.find("--out") != std::string::npos);
  CHECK_FALSE(Exists(out + ".png"));
  CHECK_FALSE(Exists(out + ".exr"));
  Run ok = Render(base + "--scene cube");
  CHECK(ok.code == 0);
  CHECK(ok.err.empty());  // no warning either: the scene's gather queries are all valid
  CHECK(Exists(out + ".exr"));
  CHECK(Exists(out + ".png"));
  CHECK(Exists(out + ".json"));
  // The written EXR serves as a reference of the right size; one of another size does not.
  CHECK(Render(base + "--scene cube --reference " + out + ".exr").code == 0);
  Run wrong = Render("--quiet --scene cube --width 9 --height 8 --spp 1 --out other.exr --reference " + out + ".exr");
  CHECK(wrong.code == 2);
  CHECK(wrong.err.find("reference") != std::string::npos);
  CHECK_FALSE(Exists("other.exr"));
  for (const char* ext : {".exr", ".png", ".json"}) std::remove((out + ext).c_str());
}

TEST_CASE("output names get .exr appended and stdout is JSON only on request", "[render][cli]") {
  const std::string out = "cli_out_" + std::to_string(getpid());
  const std::string args = "--scene cube --width 8 --height 8 --spp 1 --vrls 2 --out " + out;
  Run human = Render(args);
  CHECK(human.code == 0);
  for (const char* ext : {".exr", ".png", ".json"}) CHECK(Exists(out + ext));
  CHECK_FALSE(Exists(out));
  CHECK(std::count(human.out.begin(), human.out.end(), '\n') == 1);
  CHECK(human.out.rfind("cube: ", 0) == 0);
  CHECK(human.out.find(out + ".exr") != std::string::npos);
  Run json = Render(args + " --json");
  CHECK(json.code == 0);
  CHECK(json.out.rfind("{", 0) == 0);
  CHECK(json.out.find("\"passes\":1") != std::string::npos);
  Run quiet = Render(args + " --quiet");
  CHECK(quiet.code == 0);
  CHECK(quiet.out.empty());
  for (const char* ext : {".exr", ".png", ".json"}) std::remove((out + ext).c_str());
}
