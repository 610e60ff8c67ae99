#include "study.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "image_stats.hpp"
#include "reference.hpp"
#include "study_scene.hpp"

namespace vrlis::compare {
namespace {

// The reference's mixture: the compared samplers, each gather taken once (the effort control
// changes the noise, not the mean).
std::vector<GatherSamplers> Mixture(const StudyConfig& c) {
  std::vector<GatherSamplers> out;
  for (const Method& m : c.samplers)
    if (std::find(out.begin(), out.end(), m.sampler) == out.end()) out.push_back(m.sampler);
  return out;
}

// At least as many passes as every method renders at least: where passes are slow (fog), the
// methods' minimum outlasts the reference's seconds, and a reference shorter than the images
// it checks would hold most of the error.
int ReferencePasses(const StudyConfig& c) { return c.replicates * c.min_passes; }

// Everything a reference image depends on; a cached one is reused only if this matches.
std::string ReferenceKey(const StudyConfig& c, const vrlis::integration::TransportSettings& t) {
  std::ostringstream key;
  key << "v4 mixture scene=" << c.scene << " g=" << c.g << " size=" << c.width << "x" << c.height
      << " vrls=" << c.vrls << " seconds=" << c.reference_seconds << " passes=" << ReferencePasses(c) << " samplers=";
  for (GatherSamplers s : Mixture(c)) key << SamplerName(s) << ",";
  key << " transport=" << t.medium_to_medium << t.medium_to_surface << t.direct << t.single_scattering << t.indirect
      << t.light_caustics << t.first_segment_only << t.surface_to_surface << t.surface_to_medium << "/" << t.max_depth << "/" << t.rr_depth
      << "/" << t.vpl_bound << "/" << t.vrl_bound;
  return key.str();
}

double Rmse(const std::vector<double>& image, const std::vector<double>& reference) {
  double sum = 0;
  for (std::size_t i = 0; i < image.size(); ++i) sum += (image[i] - reference[i]) * (image[i] - reference[i]);
  return image.empty() ? 0 : std::sqrt(sum / static_cast<double>(image.size()));
}

double MeanOf(const std::vector<double>& x) {
  return x.empty() ? 0 : std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

struct Runner {
  Method sampler;
  std::vector<PassStatistics> replicates;
  PassStatistics all;
  std::vector<double> seconds;  // per replicate
  std::vector<Progression> progression;
  std::vector<vrlis::EffortPrice> prices;  // per replicate, with the effort control on or `auto`
  std::vector<vrlis::ScoreOctaves> marginal_scores;     // per replicate, with VrlMarginal as step one

  int per_replicate = 0;  // passes in each replicate

  Replicates Summary() const {
    Replicates r;
    for (std::size_t rep = 0; rep < replicates.size(); ++rep) {
      r.variance.push_back(replicates[rep].MeanPassVariance());
      r.seconds.push_back(seconds[rep] / per_replicate);
    }
    return r;
  }
};

// Whether the interval of the most efficient sampler against the runner-up still holds the
// margin, so that the verdict could go either way: such a study goes on (up to its
// extension) until the interval lies wholly above the margin ("best") or wholly below it
// ("tie"), so that a lead near the threshold is not called "best" by one run and "tie" by
// the next.
bool Undecided(const std::vector<Runner>& runners, double margin) {
  std::vector<Replicates> r;
  for (const Runner& run : runners) r.push_back(run.Summary());
  std::sort(r.begin(), r.end(), [](const Replicates& a, const Replicates& b) { return Efficiency(a) > Efficiency(b); });
  RatioInterval lead = EfficiencyRatio(r[0], r[1]);
  return lead.low <= margin && lead.high > margin;
}

// "best" for the most efficient sampler when its interval against the runner-up lies above
// the margin; otherwise "tie" for it and for every sampler its interval does not separate
// from it.
void Decide(StudyResult& r, double margin) {
  std::vector<SamplerResult*> order;
  for (SamplerResult& s : r.samplers) order.push_back(&s);
  std::sort(order.begin(), order.end(),
            [](const SamplerResult* a, const SamplerResult* b) { return a->efficiency > b->efficiency; });
  SamplerResult& top = *order[0];
  r.top_vs_runner_up = EfficiencyRatio(top.replicates, order[1]->replicates);
  if (r.top_vs_runner_up.Above(margin)) {
    top.verdict = r.verdict = "best";
    return;
  }
  r.verdict = "tie";
  top.verdict = "tie";
  for (std::size_t i = 1; i < order.size(); ++i)
    if (!EfficiencyRatio(top.replicates, order[i]->replicates).Above(margin)) order[i]->verdict = "tie";
}

}  // namespace

StudyResult RunStudy(const StudyConfig& config) {
  vrlis::scenes::MediumOverrides overrides;
  overrides.g = config.g;
  StudyScene scene = BuildStudyScene(config.scene, overrides, config.width, config.height, config.vrls);
  if (config.vrl_only) KeepVrlGathersOnly(scene);
  scene.settings.transport.effort.floor = config.effort_floor;
  PassRenderer renderer(scene.built.scene, scene.settings);
  const std::size_t values = 3 * static_cast<std::size_t>(config.width) * static_cast<std::size_t>(config.height);
  const auto replicates = static_cast<std::size_t>(config.replicates);

  std::ostringstream name;
  name << config.scene << "_g" << config.g;
  Reference reference =
      GetReference(renderer, Mixture(config), config.reference_seconds, ReferencePasses(config), config.reference_dir,
                   name.str(), ReferenceKey(config, scene.settings.transport), config.width, config.height);

  std::vector<std::uint64_t> seeds(replicates);
  for (std::size_t r = 0; r < replicates; ++r) seeds[r] = vrlis::integration::SplitMix64(config.seed * 1000003 + r);
  std::vector<Runner> runners;
  for (const Method& s : config.samplers)
    runners.push_back({s, std::vector<PassStatistics>(replicates, PassStatistics(values)), PassStatistics(values),
                       std::vector<double>(replicates, 0.0), std::vector<Progression>(replicates),
                       std::vector<vrlis::EffortPrice>(
                           replicates, vrlis::EffortPrice(config.width, config.height)),
                       std::vector<vrlis::ScoreOctaves>(replicates)});

  // Whole cycles (one pass of every replicate) so that all replicates of a sampler hold the
  // same number of passes, at least min_passes. A sampler stops once it
  // has spent its budget (or, while the study is undecided, the extended one): the others'
  // passes go on, so a sampler 20x faster than another does not keep the slow one rendering.
  std::size_t round = 0;
  auto spent = [&](const Runner& r) { return std::accumulate(r.seconds.begin(), r.seconds.end(), 0.0); };
  auto target = [&] {
    const bool short_of_budget = std::any_of(runners.begin(), runners.end(), [&](const Runner& r) {
      return r.per_replicate < config.min_passes || spent(r) < config.budget;
    });
    return !short_of_budget && Undecided(runners, config.margin) ? config.extension * config.budget : config.budget;
  };
  auto wants = [&](const Runner& r, double seconds) { return r.per_replicate < config.min_passes || spent(r) < seconds; };
  for (double goal = config.budget;
       std::any_of(runners.begin(), runners.end(), [&](const Runner& r) { return wants(r, goal); });
       goal = target()) {
    for (std::size_t rep = 0; rep < replicates; ++rep, ++round)
      for (std::size_t k = 0; k < runners.size(); ++k) {
        Runner& run = runners[(k + round) % runners.size()];
        if (!wants(run, goal)) continue;
        double seconds = 0;
        std::vector<double> pass =
            FromFilm(renderer.Render(run.sampler, seeds[rep], static_cast<std::uint64_t>(run.per_replicate), &seconds,
                                     &run.prices[rep], &run.marginal_scores[rep]));
        run.seconds[rep] += seconds;
        run.replicates[rep].Add(pass);
        run.all.Add(pass);
        run.progression[rep].seconds.push_back(run.seconds[rep]);
        run.progression[rep].rmse.push_back(Rmse(run.replicates[rep].Mean(), reference.mean));
      }
    for (Runner& run : runners)
      if (run.replicates[0].passes() > run.per_replicate) run.per_replicate = run.replicates[0].passes();
  }

  StudyResult out;
  out.config = config;
  for (const Runner& run : runners) out.passes_per_replicate = std::max(out.passes_per_replicate, run.per_replicate);
  out.reference_passes = reference.passes;
  out.reference_seconds = reference.seconds;
  out.reference_cached = reference.from_cache;
  out.reference_noise = MeanOf(reference.variance_of_mean);
  out.reference_dof = reference.dof;
  for (Runner& run : runners) {
    SamplerResult s;
    s.sampler = run.sampler;
    s.passes = run.all.passes();
    s.replicates = run.Summary();
    s.variance = PooledVariance(s.replicates);
    s.seconds = PooledSeconds(s.replicates);
    s.efficiency = Efficiency(s.replicates);
    s.image = run.all.Mean();
    std::vector<double> noise = run.all.VarianceOfMean();
    std::vector<std::vector<double>> replicate_means;
    for (const PassStatistics& rep : run.replicates) replicate_means.push_back(rep.Mean());
    s.error_to_noise =
        ErrorAgainstNoise(replicate_means, noise, reference.mean, reference.variance_of_mean, reference.dof);
    s.progression = std::move(run.progression);
    out.sampler_noise += MeanOf(noise) / static_cast<double>(runners.size());
    out.samplers.push_back(std::move(s));
  }
  const auto baseline = std::find_if(out.samplers.begin(), out.samplers.end(),
                                     [](const SamplerResult& s) { return s.sampler == kBaseline; });
  std::vector<double> widths;
  for (SamplerResult& s : out.samplers) {
    s.to_baseline = EfficiencyRatio(s.replicates, baseline->replicates);
    if (&s != &*baseline) widths.push_back(s.to_baseline.high / s.to_baseline.point);
  }
  std::sort(widths.begin(), widths.end());
  out.resolution = widths.empty() ? 1 : widths[widths.size() / 2];
  const SamplerResult* best = &*baseline;  // the baseline is a fixed published method
  for (const SamplerResult& s : out.samplers)
    if (IsFixedPublished(s.sampler) && s.efficiency > best->efficiency) best = &s;
  out.best_published = best->sampler;
  for (SamplerResult& s : out.samplers) {
    s.to_best_published = EfficiencyRatio(s.replicates, best->replicates);
    if (!s.sampler.effort) continue;
    for (const SamplerResult& fixed : out.samplers)
      if (fixed.sampler == Method{s.sampler.sampler, false})
        s.to_without_effort = EfficiencyRatio(s.replicates, fixed.replicates);
  }
  Decide(out, config.margin);
  out.reference_image = std::move(reference.mean);
  return out;
}

}  // namespace vrlis::compare
