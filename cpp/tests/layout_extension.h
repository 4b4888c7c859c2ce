// A made-up output for test_layout_extension.cc (force-included into that build only): its table row and
// its stage's line are all it takes.
#pragma once
#define ARMRT_EXTRA_OUTPUTS(X) X(hand_height, kOne, "m", "external_loads", 0, 1, "hand height, thorax frame (test)")
#define ARMRT_EXTRA_OUTPUT_STAGES(m, d, q) ((d).hand_height = (d).hand_position[1])
