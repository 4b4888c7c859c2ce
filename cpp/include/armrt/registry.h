// The models this process knows, by name. das2 is built in; a model built on demand (`armrt model build`,
// armrt.Model.load) is a shared library exporting its ModelDef, registered when it is loaded.
#pragma once

#include <string>
#include <vector>

#include "armrt/model.h"
#include "armrt/model_def.h"

namespace armrt {

// Symbols a model library exports (written by `python -m codegen.generate --entry-point`):
//   extern "C" int armrt_model_abi_version();          // kModelDefAbiVersion it was compiled against
//   extern "C" const armrt::ModelDef* armrt_model_def();
inline constexpr const char* kModelAbiSymbol = "armrt_model_abi_version";
inline constexpr const char* kModelDefSymbol = "armrt_model_def";

// The registered model of that name (built in or loaded); nullptr if none.
const ModelDef* find_model(const std::string& name);
// Comma-separated names of the registered models, for error messages.
std::string model_names();
// Every registered model, built-in first, then in the order they were loaded.
std::vector<const ModelDef*> registered_models();
// Adds a model. A second model under a registered name is accepted only if it was generated from the
// same model file (same source_hash): find_model keeps returning the first. Otherwise throws
// std::invalid_argument naming both hashes. Not for the real-time path (takes a lock).
void register_model(const ModelDef& def);
// Loads a model library (dlopen), checks that it was compiled against this engine's ModelDef layout
// (kModelDefAbiVersion) and that its sizes fit the engine, registers its model and returns it. The
// library is never unloaded, so the ModelDef outlives every Arm using it. Throws
// std::runtime_error naming the file and the problem.
const ModelDef& load_model_library(const std::string& path);
// The one immutable Model of def (model_init'ed on first use, then shared by every arm of def in this process,
// never freed). Throws std::invalid_argument if the engine cannot take def. Not for the real-time path (takes
// a lock): an arm keeps the reference it got.
const Model& shared_model(const ModelDef& def);
// Whether a ModelDef's sizes and tables are usable by this engine; the reason in *why otherwise.
bool model_fits_engine(const ModelDef& def, std::string* why);

}  // namespace armrt
