// Merges the per-process summary files of tests/lib into one table (summary.txt beside
// them): per sampler and Real type, the worst value of each metric and where it was seen.
// Fails if the suite ran more chi-square tests than the budget its significance assumes.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "stats.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: vrlis_lib_summary DIR\n";
    return 2;
  }
  namespace fs = std::filesystem;
  std::map<std::string, std::pair<double, std::string>> worst;
  std::map<std::string, double> counts;
  for (const auto& entry : fs::directory_iterator(argv[1])) {
    if (entry.path().extension() != ".txt" || entry.path().filename() == "summary.txt") continue;
    std::ifstream in(entry.path());
    std::string line;
    while (std::getline(in, line)) {
      std::istringstream s(line);
      std::string kind, label, metric, note;
      double value = 0;
      s >> kind >> label >> metric >> value;
      std::getline(s, note);
      std::string key = label + " " + metric;
      if (kind == "max") {
        auto it = worst.find(key);
        if (it == worst.end() || value > it->second.first) worst[key] = {value, note};
      } else if (kind == "count") {
        counts[key] += value;
      }
    }
  }
  std::ostringstream table;
  table.precision(4);
  for (const auto& [key, v] : worst) table << key << " = " << v.first << "  (" << v.second.substr(v.second.find_first_not_of(' ') == std::string::npos ? 0 : v.second.find_first_not_of(' ')) << ")\n";
  for (const auto& [key, n] : counts) table << key << " = " << n << "\n";
  table << "chi-square significance per test: " << vrlis::test::kChiSquareAlpha << " (Bonferroni, 0.01 / "
        << vrlis::test::kChiSquareBudget << ")\n";
  std::cout << table.str();
  std::ofstream(fs::path(argv[1]) / "summary.txt") << table.str();
  double tests = counts["all chi_square_tests"];
  if (tests > vrlis::test::kChiSquareBudget) {
    std::cerr << "the suite ran " << tests << " chi-square tests, more than the budget " << vrlis::test::kChiSquareBudget
              << " its per-test significance assumes\n";
    return 1;
  }
  return 0;
}
