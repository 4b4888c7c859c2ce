// An engine built with one more output row (layout_extension.h): Data holds it, forward() fills it, a
// recording keeps it and the table listings (what the bindings and armrt.Result read) name it, with no
// other change to the engine.
#include <doctest/doctest.h>

#include <cstring>

#include "armrt/arm.h"
#include "armrt/layouts.h"
#include "armrt/recorder.h"

using namespace armrt;

TEST_CASE("a made-up output is one table row and one stage line: Data, forward, recording and listings follow") {
  const ModelDef* def = find_model("das2");
  REQUIRE(def);
  Arm arm(*def, Integrator::kRos2, 1e-3);
  for (int i = 0; i < arm.model.num_elements; ++i) arm.data.excitation[i] = 0.2;
  Recording r;
  const long steps = simulate_recorded(arm, arm.data.excitation.data(), true, 20, 1, r);
  REQUIRE(steps == 20);
  REQUIRE(r.rows() == 21);
  const std::vector<double>& height = r[Channel::hand_height];
  const std::vector<double>& hand = r[Channel::hand_position];
  REQUIRE(height.size() == 21u);
  for (long k = 0; k < r.rows(); ++k) CHECK(height[k] == hand[3 * k + 1]);
  CHECK(height.front() != height.back());  // the arm moved: the values are the stage's, not a constant
  CHECK(arm.data.hand_height == arm.data.hand_position[1]);
  // Listed where the bindings read the tables.
  const LayoutRow* rec = recorded_channels();
  CHECK(std::strcmp(rec[static_cast<int>(Channel::hand_height)].name, "hand_height") == 0);
  CHECK(std::strcmp(rec[static_cast<int>(Channel::hand_height)].unit, "m") == 0);
  int n = 0;
  const LayoutRow* out = output_rows(&n);
  bool listed = false;
  for (int k = 0; k < n; ++k) listed |= std::strcmp(out[k].name, "hand_height") == 0;
  CHECK(listed);
}
