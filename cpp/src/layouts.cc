// layouts.cc: the tables of layouts.h -> rows a program can walk (names, sizes, units, stages).
#include "armrt/layouts.h"

namespace armrt {

namespace {

#define ARMRT_ROW_EXTRA(name, size, unit, girdle_only, description) \
  {#name, SizeRule::size, unit, "recording", girdle_only != 0, description},
#define ARMRT_ROW_INPUT(name, size, unit, girdle_only, description) \
  {#name, SizeRule::size, unit, "input", girdle_only != 0, description},
#define ARMRT_ROW_STATE(name, size, unit, description) {#name, SizeRule::size, unit, "state", false, description},
#define ARMRT_ROW_OUT(name, size, unit, stage, girdle_only, recorded, description) \
  {#name, SizeRule::size, unit, stage, girdle_only != 0, description},
#define ARMRT_ROW_RECORDED_OUT(name, size, unit, stage, girdle_only, recorded, description) \
  ARMRT_ROW_RECORDED_OUT_##recorded(name, size, unit, stage, girdle_only, description)
#define ARMRT_ROW_RECORDED_OUT_0(...)
#define ARMRT_ROW_RECORDED_OUT_1(name, size, unit, stage, girdle_only, description) \
  {#name, SizeRule::size, unit, stage, girdle_only != 0, description},

const LayoutRow kRecorded[] = {
    ARMRT_RECORDED_EXTRA_FIRST(ARMRT_ROW_EXTRA) ARMRT_STATE_BLOCKS(ARMRT_ROW_STATE)
        ARMRT_RECORDED_INPUTS(ARMRT_ROW_INPUT) ARMRT_OUTPUTS(ARMRT_ROW_RECORDED_OUT)
            ARMRT_RECORDED_EXTRA_LAST(ARMRT_ROW_EXTRA)};
static_assert(sizeof kRecorded / sizeof kRecorded[0] == kNumChannels, "one row per Channel");

const LayoutRow kOutputs[] = {ARMRT_OUTPUTS(ARMRT_ROW_OUT)};

#define ARMRT_ROW_SNAP(stage) ARMRT_ROW_SNAP_##stage
#define ARMRT_ROW_SNAP_time(name, size, unit, description) {#name, SizeRule::size, unit, "time", false, description},
#define ARMRT_ROW_SNAP_input(name, size, unit, description) {#name, SizeRule::size, unit, "input", false, description},
#define ARMRT_ROW_SNAP_stimulation(name, size, unit, description) \
  {#name, SizeRule::size, unit, "stimulation", false, description},
#define ARMRT_ROW_SNAP_integrator(name, size, unit, description) \
  {#name, SizeRule::size, unit, "integrator", false, description},
const LayoutRow kSnapshot[] = {ARMRT_SNAPSHOT_TIME(ARMRT_ROW_SNAP(time)) ARMRT_STATE_BLOCKS(ARMRT_ROW_STATE)
                                   ARMRT_SNAPSHOT_INPUTS(ARMRT_ROW_SNAP(input))
                                       ARMRT_SNAPSHOT_STIMULATION(ARMRT_ROW_SNAP(stimulation))
                                       ARMRT_SNAPSHOT_INTEGRATOR(ARMRT_ROW_SNAP(integrator))};
static_assert(sizeof kSnapshot / sizeof kSnapshot[0] == kNumSnapshotParts, "one row per SnapshotPart");

}  // namespace

const LayoutRow* recorded_channels() { return kRecorded; }

const LayoutRow* snapshot_rows() { return kSnapshot; }

const LayoutRow* output_rows(int* count) {
  *count = static_cast<int>(sizeof kOutputs / sizeof kOutputs[0]);
  return kOutputs;
}

}  // namespace armrt
