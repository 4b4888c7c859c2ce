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

}  // namespace

const LayoutRow* recorded_channels() { return kRecorded; }

const LayoutRow* output_rows(int* count) {
  *count = static_cast<int>(sizeof kOutputs / sizeof kOutputs[0]);
  return kOutputs;
}

}  // namespace armrt
