#pragma once
// vrlis: importance sampling for anisotropic virtual ray lights. The whole core library.
#include "core/phase.hpp"
#include "core/query.hpp"
#include "core/running_moments.hpp"
#include "core/two_point_direction.hpp"
#include "angle/angle_domain.hpp"
#include "angle/phase_product.hpp"
#include "angle/full_product.hpp"
#include "angle/segment_sampler.hpp"
#include "samplers/equiangular.hpp"
#include "samplers/novak.hpp"
#include "samplers/cauchy_sum.hpp"
#include "samplers/cauchy_mixture.hpp"
#include "samplers/full_product.hpp"
#include "samplers/vrl_point.hpp"
#include "samplers/vrl_marginal.hpp"
#include "samplers/auto_sampler.hpp"
#include "method.hpp"
#include "gather/medium_gather.hpp"
#include "gather/surface_gather.hpp"
#include "gather/point_light_gather.hpp"
#include "effort/policy.hpp"
#include "effort/bounds.hpp"
#include "effort/marginal_fits.hpp"
#include "effort/work.hpp"
#include "effort/record.hpp"
#include "effort/call.hpp"
#include "effort/price.hpp"
#include "gather/gather_vrls.hpp"
#include "gather/gather_instances.hpp"
#include "xyz.hpp"

namespace vrlis {
static_assert(IsSegmentSampler<Equiangular<float>>::value && IsSegmentSampler<Equiangular<double>>::value);
static_assert(IsSegmentSampler<Novak<float>>::value && IsSegmentSampler<Novak<double>>::value);
static_assert(IsSegmentSampler<CauchySum<float>>::value && IsSegmentSampler<CauchySum<double>>::value);
static_assert(IsSegmentSampler<CauchyMixture<float>>::value && IsSegmentSampler<CauchyMixture<double>>::value);
static_assert(IsSegmentSampler<FullProduct<float>>::value && IsSegmentSampler<FullProduct<double>>::value);
static_assert(IsSegmentSampler<Auto<float>>::value && IsSegmentSampler<Auto<double>>::value);
}  // namespace vrlis
