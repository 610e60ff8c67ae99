#pragma once
// The transport most render tests were written and their thresholds set for: Novák's samplers,
// every VRL gathered once. The default (`auto` with the effort control) has tests of its own
// (determinism_test.cpp, effort_test.cpp).
#include <vrlis_integration/transport.hpp>

namespace vrlis::test {

inline integration::TransportSettings Uncontrolled(integration::TransportSettings t) {
  t.sampling = FixedSamplers<NovakEntry>{};
  t.effort.on = false;
  return t;
}

}  // namespace vrlis::test
