#pragma once
// The light pass: trace light paths from the lights and record every medium segment as a
// VRL and, for the VPL gathers (vpl.hpp), every diffuse vertex as a VPL.
#include <cstdint>
#include <vector>

#include "scene.hpp"
#include "transport.hpp"
#include "vpl.hpp"
#include "vrl.hpp"

namespace vrlis::integration {

// The rotation of a point light's Fibonacci lattice in pass `pass`: uniformly random from a
// stream of its own named by (seed, pass, light), so that every renderer of a pass meets the
// same beams; the identity for a light whose lattice is fixed.
Rotation LatticeRotation(const PointLight& light, std::uint64_t seed, std::uint64_t pass, std::size_t light_index);

// `count` light paths of one pass, each starting with flux (light power / count); the VRLs
// (and the VPLs, if `vpls` is set) come out in path order, whatever the thread count. A path
// whose first vertex is specular makes no VPLs: the remainder, which would share their
// connections, cannot sample light through a specular surface from a delta light. If `work`
// is set, the paths' counted work (work.hpp) is added to it.
std::vector<Vrl> TraceLightPaths(const Scene& scene, const TransportSettings& transport, int count,
                                 std::uint64_t seed, std::uint64_t pass, std::vector<Vpl>* vpls = nullptr,
                                 double* work = nullptr);

}  // namespace vrlis::integration
