#include "armrt/registry.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "armrt/model.h"
#include "das2.h"
#include "das3.h"
#include "participant_A.h"

namespace armrt {

namespace {

// Built-in models. das3: the 11-DOF shoulder-girdle model (models/das3.json, docs/das3.md). participant_A: participant A's elbow-forearm model (ELx, PSy; models/participant_A.json);
// its injured, paralysed and FES variants share its geometry and are applied as profiles
// (Arm.apply_profile), so they need no code of their own.
struct Registry {
  std::mutex mutex;
  std::vector<const ModelDef*> models{&generated::das2::model_def(), &generated::das3::model_def(),
                                      &generated::participant_A::model_def()};
  // The one Model of each ModelDef, built on first use and never freed (like the model libraries).
  std::map<const ModelDef*, std::unique_ptr<const Model>> shared;
  std::vector<std::unique_ptr<const Model>> replaced;
};

// Whether m was built from def's tables as they are now (the constants model_init copied).
bool same_tables(const Model& m, const ModelDef& def) {
  auto fresh = std::make_unique<Model>();
  model_init(*fresh, def);
  const Model& f = *fresh;
  for (int i = 0; i < def.num_elements; ++i)
    if (std::memcmp(&f.element[i], &m.element[i], sizeof(ElementConstants)) != 0) return false;
  return f.gravity_base == m.gravity_base && f.dof_elements_begin == m.dof_elements_begin &&
         f.dof_elements_end == m.dof_elements_end && f.num_element_runs == m.num_element_runs &&
         std::memcmp(f.element_runs.data(), m.element_runs.data(), sizeof m.element_runs) == 0;
}

Registry& registry() {
  static Registry r;
  return r;
}

const ModelDef* find_locked(Registry& r, const std::string& name) {
  for (const ModelDef* def : r.models)
    if (name == def->name) return def;
  return nullptr;
}

}  // namespace

const Model& shared_model(const ModelDef& def) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  auto it = r.shared.find(&def);
  // A registered ModelDef (built in, or a library never unloaded) lives as long as the process and never
  // changes: its Model is returned as it is. Any other (a test's copy on the stack) may reuse the address of
  // one that is gone: a Model whose tables are not this def's is replaced (and kept: arms may still use it).
  const bool registered = std::find(r.models.begin(), r.models.end(), &def) != r.models.end();
  if (it != r.shared.end() &&
      (registered || (it->second->def == &def && it->second->num_elements == def.num_elements &&
                      it->second->num_dofs == def.num_dofs && same_tables(*it->second, def))))
    return *it->second;
  auto m = std::make_unique<Model>();
  model_init(*m, def);  // throws for a model the engine cannot take; nothing is kept then
  if (it != r.shared.end()) {
    r.replaced.push_back(std::move(it->second));
    it->second = std::move(m);
    return *it->second;
  }
  return *r.shared.emplace(&def, std::move(m)).first->second;
}

const ModelDef* find_model(const std::string& name) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return find_locked(r, name);
}

std::string model_names() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  std::string out;
  for (const ModelDef* def : r.models) out += (out.empty() ? "" : ", ") + std::string(def->name);
  return out;
}

std::vector<const ModelDef*> registered_models() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return r.models;
}

void register_model(const ModelDef& def) {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  const ModelDef* known = find_locked(r, def.name);
  if (known == nullptr) {
    r.models.push_back(&def);
    return;
  }
  if (std::strcmp(known->source_hash, def.source_hash) != 0)
    throw std::invalid_argument(std::string("a different model named '") + def.name +
                                "' is already registered (model file sha256 " + known->source_hash +
                                "; this one " + def.source_hash +
                                "): give the new model file another 'name'");
}

bool model_fits_engine(const ModelDef& def, std::string* why) {
  auto fail = [why](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (def.name == nullptr || def.source_hash == nullptr) return fail("its name or source hash is missing");
  if (def.num_dofs < 1 || def.num_dofs > kMaxDofs)
    return fail("it has " + std::to_string(def.num_dofs) + " DOFs; this engine takes 1 to " +
                std::to_string(kMaxDofs));
  if (def.num_elements < 1 || def.num_elements > kMaxElements)
    return fail("it has " + std::to_string(def.num_elements) + " elements; this engine takes 1 to " +
                std::to_string(kMaxElements));
  if (!def.dofs || !def.elements || (def.num_muscles > 0 && !def.muscles) || (def.num_groups > 0 && !def.groups))
    return fail("a parameter table is missing");
  for (int i = 0; i < def.num_elements; ++i)
    if (!def.elements[i].name || !def.elements[i].muscle || !def.elements[i].osim_name)
      return fail("element " + std::to_string(i) + " has no name, muscle or OpenSim name");
  for (int j = 0; j < def.num_dofs; ++j)
    if (!def.dofs[j].name || !def.dofs[j].osim_name) return fail("DOF " + std::to_string(j) + " has no name");
  if (!def.mass_matrix || !def.bias_force || !def.dynamics || !def.hand_position || !def.hand_jacobian ||
      !def.arm_momentum_rate || !def.body_poses || !def.muscle_lengths || !def.muscle_paths || !def.gh_directions)
    return fail("a model function is missing");
  if (!def.base_body || !def.body_names) return fail("the base or body names are missing");
  for (int b = 0; b < def.num_bodies && b < kMaxBodies; ++b)
    if (!def.body_names[b]) return fail("body " + std::to_string(b) + " has no name");
  if (def.girdle && (!def.girdle->points || !def.girdle->contact_point_names))
    return fail("the girdle forces' points function or contact point names are missing");
  return true;
}

const ModelDef& load_model_library(const std::string& path) {
  // RTLD_LOCAL: the library's generated symbols (armrt::generated::<name>::...) never interpose on
  // another model's; RTLD_NOW: an unresolved symbol fails here, not mid-simulation.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* err = dlerror();
    throw std::runtime_error("cannot load model library " + path + ": " + (err ? err : "dlopen failed"));
  }
  // Never dlclose: Models and Arms hold raw pointers into the library's tables and functions.
  using AbiFn = int (*)();
  using DefFn = const ModelDef* (*)();
  auto abi = reinterpret_cast<AbiFn>(dlsym(handle, kModelAbiSymbol));
  auto get = reinterpret_cast<DefFn>(dlsym(handle, kModelDefSymbol));
  if (abi == nullptr || get == nullptr)
    throw std::runtime_error("model library " + path + " does not export " + kModelAbiSymbol + " and " +
                             kModelDefSymbol + " (not built by `armrt model build`?)");
  if (abi() != kModelDefAbiVersion)
    throw std::runtime_error("model library " + path + " was built for ModelDef layout " +
                             std::to_string(abi()) + ", this engine has " + std::to_string(kModelDefAbiVersion) +
                             ": rebuild it (armrt model build)");
  const ModelDef* def = get();
  if (def == nullptr) throw std::runtime_error("model library " + path + " returned no ModelDef");
  std::string why;
  if (!model_fits_engine(*def, &why))
    throw std::runtime_error("model library " + path + " cannot run on this engine: " + why);
  register_model(*def);
  return *def;
}

}  // namespace armrt
