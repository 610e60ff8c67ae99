#pragma once
// One equal-time study: every method renders the same scene for the same wall-clock budget,
// interleaved pass by pass (the method that has spent the least time goes next), each
// timing its own passes; the running image is scored against a converged reference.
#include <cstdint>
#include <string>
#include <vector>

#include <vrlis/method.hpp>

namespace vrl_compare {

struct StudyConfig {
  std::string scene;
  float g = 0;
  int width = 48, height = 48;
  int vrls = 32;                 // light paths per pass
  double budget = 5;             // seconds per method
  double reference_seconds = 30;
  vrlis::Method reference_method = vrlis::CameraSamplers::Of<vrlis::FullProductEntry>();
  std::vector<vrlis::Method> methods;
  std::uint64_t seed = 1;
  std::string out_dir;           // this study's folder
  std::string reference_dir;     // shared cache of references
};

struct Checkpoint {
  double seconds = 0;
  int passes = 0;
  double rmse = 0;
};

struct MethodResult {
  vrlis::Method method{};
  std::vector<Checkpoint> curve;  // one point per pass
  double rmse_at_budget = 0;      // log-log interpolation at exactly the budget
  std::vector<double> image;      // the running mean at the end
};

struct StudyResult {
  StudyConfig config;
  std::vector<MethodResult> methods;
  std::vector<double> reference_image;
  int reference_passes = 0;
  double reference_seconds = 0;
  bool reference_cached = false;
  double reference_noise_rmse = 0;  // sqrt of the reference's mean variance, already subtracted
};

StudyResult RunStudy(const StudyConfig& config);

// RMSE against the reference with the reference's own noise subtracted (an unbiased
// estimate of the error against the true image), over all pixels and channels.
double Rmse(const std::vector<double>& image, const std::vector<double>& reference,
            const std::vector<double>& reference_variance);

}  // namespace vrl_compare
