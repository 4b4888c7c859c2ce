// The model registry (cpp/src/registry.cc): das2 built in, registration by name, refusal of a different
// model under a registered name, and the checks on a model library before it is used.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "armrt/model.h"
#include "armrt/registry.h"

using namespace armrt;

TEST_CASE("das2 is built in and registered first") {
  const ModelDef* das2 = find_model("das2");
  REQUIRE(das2 != nullptr);
  CHECK(registered_models().front() == das2);
  CHECK(model_names().rfind("das2", 0) == 0);
  CHECK(model_fits_engine(*das2, nullptr));
}

TEST_CASE("a model registers under its name; a different model under a taken name is refused") {
  const ModelDef& das2 = *find_model("das2");
  static ModelDef renamed = das2;  // registered models must outlive the registry: static
  renamed.name = "registry_test_copy";
  register_model(renamed);
  CHECK(find_model("registry_test_copy") == &renamed);
  CHECK(model_names().find("registry_test_copy") != std::string::npos);

  static ModelDef same = das2;  // same name, same model file: accepted, the first stays
  register_model(same);
  CHECK(find_model("das2") == &das2);

  static ModelDef other = das2;
  other.source_hash = "0000000000000000000000000000000000000000000000000000000000000000";
  CHECK_THROWS_AS(register_model(other), std::invalid_argument);
  CHECK(find_model("das2") == &das2);
}

TEST_CASE("model_fits_engine names what does not fit") {
  ModelDef m = *find_model("das2");
  std::string why;
  m.num_dofs = kMaxDofs + 1;
  CHECK_FALSE(model_fits_engine(m, &why));
  CHECK(why.find("DOFs") != std::string::npos);
  m = *find_model("das2");
  m.num_elements = kMaxElements + 1;
  CHECK_FALSE(model_fits_engine(m, &why));
  CHECK(why.find("elements") != std::string::npos);
  m = *find_model("das2");
  m.muscle_paths = nullptr;
  CHECK_FALSE(model_fits_engine(m, &why));
  CHECK(why.find("function") != std::string::npos);
}

TEST_CASE("loading a missing or foreign library fails with its path") {
  try {
    load_model_library("/nonexistent/libarmrt_model.so");
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("/nonexistent/libarmrt_model.so") != std::string::npos);
  }
  // A real shared library without the entry point (libm is always there on glibc).
  try {
    load_model_library("libm.so.6");
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("armrt_model_def") != std::string::npos);
  }
}
