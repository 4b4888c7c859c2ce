// The name service (names.h) on das2 and on the pendulum test model.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "armrt/names.h"
#include "pendulum2.h"
#include "test_util.h"

using namespace armrt;

TEST_SUITE("names") {

TEST_CASE("elements, muscles, groups and OpenSim aliases resolve to element indices") {
  const ModelDef& def = armrt_test::das2();
  std::vector<int> ix;
  REQUIRE(find_elements(def, "bicl", ix));
  CHECK(ix == std::vector<int>{armrt_test::element_index(def, "bicl")});
  REQUIRE(find_elements(def, "deltscap", ix));
  CHECK(ix.size() == 11);
  REQUIRE(find_elements(def, "rotator_cuff", ix));
  CHECK(ix.size() == 24);
  REQUIRE(find_elements(def, "delt_scap_1", ix));  // OpenSim force name
  CHECK(ix == std::vector<int>{0});
  REQUIRE(find_elements(def, "delt_scap", ix));    // OpenSim muscle: every delt_scap_k
  CHECK(ix.size() == 11);
  ix = {7};
  CHECK_FALSE(find_elements(def, "nope", ix));
  CHECK(ix == std::vector<int>{7});  // untouched
  CHECK(find_dof(def, "ELx") == 3);
  CHECK(find_dof(def, "EL_x") == 3);
  CHECK(find_dof(def, "ELy") == -1);
}

TEST_CASE("similarity is difflib's ratio; suggestions as difflib.get_close_matches") {
  // Values from Python: difflib.SequenceMatcher(None, a, b).ratio().
  CHECK(similarity("bicb", "bicbb") == doctest::Approx(8.0 / 9.0));
  CHECK(similarity("abcd", "bcde") == doctest::Approx(0.75));
  CHECK(similarity("", "") == 1.0);
  CHECK(similarity("abc", "xyz") == 0.0);
  const ModelDef& def = armrt_test::das2();
  const auto close = close_matches(def, "bicbb", NameKind::kElementsMusclesGroups);
  REQUIRE(!close.empty());
  CHECK(close[0] == "bicb");
  CHECK(unknown_names_message(def, {"tricepz"}).find("(did you mean 'triceps'") != std::string::npos);
  CHECK(unknown_dof_message(def, "ELy") == "unknown DOF 'ELy'; did you mean 'ELx'?");  // as difflib
  CHECK(unknown_dof_message(def, "zz").find("DOFs are ['GHy', 'GHz', 'GHyy', 'ELx', 'PSy']") != std::string::npos);
}

TEST_CASE("several unknown names are counted before the phrase; another case is suggested first") {
  const ModelDef& def = armrt_test::das2();
  const std::string two = unknown_names_message(def, {"bicepz", "tricepz"});
  CHECK(two.rfind("2 unknown element, muscle or group names: 'bicepz'", 0) == 0);
  const auto close = close_matches(def, "BICB", NameKind::kElementsMusclesGroups);
  REQUIRE(!close.empty());
  CHECK(close[0] == "bicb");
  CHECK(close_matches(def, "elx", NameKind::kDofs)[0] == "ELx");
  CHECK(unknown_names_message(def, {"BICB"}).find("(did you mean 'bicb'") != std::string::npos);
}

TEST_CASE("the same service on another model") {
  const ModelDef& def = generated::pendulum2::model_def();
  std::vector<int> ix;
  REQUIRE(find_elements(def, "elbow", ix));
  CHECK(ix == std::vector<int>{0, 1, 2});
  CHECK(find_dof(def, "PS_y") == 1);
  CHECK(close_matches(def, "flexer", NameKind::kElementsMusclesGroups)[0] == "flexor");
}

}  // TEST_SUITE
