// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/participant_A_FES.json --out cpp/tests/generated`
// from the model file participant_A_FES.json (sha256 a6b73006f7bd66708bb0af94f23a21910ada134588c9d0322f3a4473e2ebce21).
// Change the model file or the generator and regenerate instead.

#include "participant_A_FES.h"

namespace armrt::generated::participant_A_FES {

namespace {

const DofParams kDofs[2] = {
    {.name = "ELx", .osim_name = "EL_x", .range_min = 0.087266460000000004, .range_max = 2.44346095, .rest = 0.65690320659830481},
    {.name = "PSy", .osim_name = "PS_y", .range_min = 0.087266460000000004, .range_max = 2.7925268000000001, .rest = 1.4214063526017877},
};

const ElementParams kElements[42] = {
    {.name = "bicl", .muscle = "bicl", .osim_name = "bic_l", .fmax = 204.19802598230831, .lceopt = 0.1204078636120315, .lslack = 0.21761018694589282, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015899995389001335, .tdeact = 0.057200057200057192, .peeslack = 1.3, .mass = 0.066199999999999995, .crosses_gh = 1, .dof_mask = 3, .max_activation = 0.42033352404756757},
    {.name = "bicb1", .muscle = "bicb", .osim_name = "bic_b_1", .fmax = 101.80477952432086, .lceopt = 0.11073064426620616, .lslack = 0.18104933545406185, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015899995389001335, .tdeact = 0.057200057200057192, .peeslack = 1.5, .mass = 0.020789999999999999, .crosses_gh = 1, .dof_mask = 3, .max_activation = 0.42033352404756757},
    {.name = "bicb2", .muscle = "bicb", .osim_name = "bic_b_2", .fmax = 189.48635264064345, .lceopt = 0.10874317116399219, .lslack = 0.18237431752220451, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015899995389001335, .tdeact = 0.057200057200057192, .peeslack = 1.6000000000000001, .mass = 0.03107, .crosses_gh = 1, .dof_mask = 3, .max_activation = 0.42033352404756757},
    {.name = "triclong1", .muscle = "triclong", .osim_name = "tric_long_1", .fmax = 31.197341058850075, .lceopt = 0.09500193431334622, .lslack = 0.19236006739438455, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.5, .mass = 0.026970000000000001, .crosses_gh = 1, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclong2", .muscle = "triclong", .osim_name = "tric_long_2", .fmax = 41.409923557935521, .lceopt = 0.083143790193397224, .lslack = 0.20696291928958016, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.5, .mass = 0.02955, .crosses_gh = 1, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclong3", .muscle = "triclong", .osim_name = "tric_long_3", .fmax = 39.591244482755926, .lceopt = 0.11186173461017568, .lslack = 0.20613574087082248, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.02964, .crosses_gh = 1, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclong4", .muscle = "triclong", .osim_name = "tric_long_4", .fmax = 45.746773660286877, .lceopt = 0.11594344130728815, .lslack = 0.20777140338671457, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.032030000000000003, .crosses_gh = 1, .dof_mask = 1, .max_activation = 0.5},
    {.name = "tricmed1", .muscle = "tricmed", .osim_name = "tric_med_1", .fmax = 36.793276674787307, .lceopt = 0.076371319299570403, .lslack = 0.082806572970413994, .pennopt = 0.29670597283900002, .vmax = 10.0, .tact = 0.015899995389001335, .tdeact = 0.057200057200057192, .peeslack = 1.3, .mass = 0.0184, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "tricmed2", .muscle = "tricmed", .osim_name = "tric_med_2", .fmax = 35.813987941998292, .lceopt = 0.072956953646394027, .lslack = 0.10589612159282548, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.017649999999999999, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "tricmed3", .muscle = "tricmed", .osim_name = "tric_med_3", .fmax = 33.575613695623396, .lceopt = 0.056670384516401211, .lslack = 0.010072643095107857, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.011950000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "tricmed4", .muscle = "tricmed", .osim_name = "tric_med_4", .fmax = 29.518560374068901, .lceopt = 0.070096557394039624, .lslack = 0.03796113832063272, .pennopt = 0.13962634016, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.013950000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "tricmed5", .muscle = "tricmed", .osim_name = "tric_med_5", .fmax = 14.969127772632097, .lceopt = 0.076000633999944084, .lslack = 0.069502438527829918, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0077000000000000002, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "brachialis1", .muscle = "brachialis", .osim_name = "brachialis_1", .fmax = 53.780300812738624, .lceopt = 0.083139637853170051, .lslack = 0.076590967748297059, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.029100000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.12233917382333628},
    {.name = "brachialis2", .muscle = "brachialis", .osim_name = "brachialis_2", .fmax = 31.630094626941922, .lceopt = 0.090247603432485141, .lslack = 0.056061470337913123, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.015900000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.14299319451601231},
    {.name = "brachialis3", .muscle = "brachialis", .osim_name = "brachialis_3", .fmax = 34.010996192700254, .lceopt = 0.082253660788472238, .lslack = 0.037250508449032257, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.1000000000000001, .mass = 0.01465, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.15473610642720773},
    {.name = "brachialis4", .muscle = "brachialis", .osim_name = "brachialis_4", .fmax = 20.089889697913598, .lceopt = 0.071840246074855271, .lslack = 0.030044007923125483, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.0070000000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.16494162313557964},
    {.name = "brachialis5", .muscle = "brachialis", .osim_name = "brachialis_5", .fmax = 23.572423939427225, .lceopt = 0.058891728483027289, .lslack = 0.019884283122702268, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0066, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.16670738288138068},
    {.name = "brachialis6", .muscle = "brachialis", .osim_name = "brachialis_6", .fmax = 27.745305504160974, .lceopt = 0.044668912306677876, .lslack = 0.033123134125714528, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0041000000000000003, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.19055841692418252},
    {.name = "brachialis7", .muscle = "brachialis", .osim_name = "brachialis_7", .fmax = 26.444176710095494, .lceopt = 0.059346311835286505, .lslack = 0.0072629946851558366, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0064999999999999997, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.16007370889888314},
    {.name = "brachiorad1", .muscle = "brachiorad", .osim_name = "brachiorad_1", .fmax = 7.569368563949844, .lceopt = 0.15545157075401794, .lslack = 0.11535990712495939, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0047000000000000002, .crosses_gh = 0, .dof_mask = 3, .max_activation = 0.18022306104642485},
    {.name = "brachiorad2", .muscle = "brachiorad", .osim_name = "brachiorad_2", .fmax = 16.812327134089749, .lceopt = 0.15616998050770317, .lslack = 0.11589303575184172, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.014, .crosses_gh = 0, .dof_mask = 3, .max_activation = 0.14644884263144381},
    {.name = "brachiorad3", .muscle = "brachiorad", .osim_name = "brachiorad_3", .fmax = 12.544791167801041, .lceopt = 0.1034484257277607, .lslack = 0.14964115616529738, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0059699999999999996, .crosses_gh = 0, .dof_mask = 3, .max_activation = 0.17231855999726706},
    {.name = "pronteres1", .muscle = "pronteres", .osim_name = "pron_teres_1", .fmax = 106.22895692661974, .lceopt = 0.060979617860032288, .lslack = 0.085071565244077829, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0275, .crosses_gh = 0, .dof_mask = 3, .max_activation = 0.14878005171795483},
    {.name = "pronteres2", .muscle = "pronteres", .osim_name = "pron_teres_2", .fmax = 29.369182209124279, .lceopt = 0.037890879211192559, .lslack = 0.046903287821527362, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0043299999999999996, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "supinator1", .muscle = "supinator", .osim_name = "supinator_1", .fmax = 9.789727403041427, .lceopt = 0.025874336434762221, .lslack = 0.024614537282507877, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00084000000000000003, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "supinator2", .muscle = "supinator", .osim_name = "supinator_2", .fmax = 48.323760797991724, .lceopt = 0.025195983045086724, .lslack = 0.022385661859288589, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.00364, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "supinator3", .muscle = "supinator", .osim_name = "supinator_3", .fmax = 26.244801123047228, .lceopt = 0.024420722028314867, .lslack = 0.014536144064473134, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0033600000000000001, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "supinator4", .muscle = "supinator", .osim_name = "supinator_4", .fmax = 30.82722671596024, .lceopt = 0.025486705926376259, .lslack = 0.014051605928990712, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.00296, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "supinator5", .muscle = "supinator", .osim_name = "supinator_5", .fmax = 59.363240635463974, .lceopt = 0.026552689824437602, .lslack = 0.013470160166411775, .pennopt = 0.03490658504, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0067600000000000004, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "pronquad1", .muscle = "pronquad", .osim_name = "pron_quad_1", .fmax = 15.205321285574982, .lceopt = 0.036534194341452428, .lslack = 0.004845383864914116, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.1000000000000001, .mass = 0.0016299999999999999, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "pronquad2", .muscle = "pronquad", .osim_name = "pron_quad_2", .fmax = 37.075988888114345, .lceopt = 0.037406349040823281, .lslack = 0.0048453820001066426, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00347, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "pronquad3", .muscle = "pronquad", .osim_name = "pron_quad_3", .fmax = 45.615963856724946, .lceopt = 0.034111484653784246, .lslack = 0.0048453813428670804, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0049300000000000004, .crosses_gh = 0, .dof_mask = 2, .max_activation = 0.14878005171795483},
    {.name = "triclat1", .muscle = "triclat", .osim_name = "tric_lat_1", .fmax = 21.404453730959915, .lceopt = 0.071262786981108356, .lslack = 0.16048229205376247, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.012500000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclat2", .muscle = "triclat", .osim_name = "tric_lat_2", .fmax = 57.358340063356643, .lceopt = 0.072036447856348565, .lslack = 0.1664549774226331, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0332, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclat3", .muscle = "triclat", .osim_name = "tric_lat_3", .fmax = 30.637747497256349, .lceopt = 0.061730693191384862, .lslack = 0.1798282845864885, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0152, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclat4", .muscle = "triclat", .osim_name = "tric_lat_4", .fmax = 38.472057359568474, .lceopt = 0.060059412907026891, .lslack = 0.14779510699691573, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.016199999999999999, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "triclat5", .muscle = "triclat", .osim_name = "tric_lat_5", .fmax = 12.171159964663481, .lceopt = 0.0600320742619544, .lslack = 0.14772783164775613, .pennopt = 0.29670597283900002, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0058500000000000002, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.5},
    {.name = "anconeus1", .muscle = "anconeus", .osim_name = "anconeus_1", .fmax = 4.3368501023513559, .lceopt = 0.024880826177311174, .lslack = 0.0063189399815393463, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00083000000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.0},
    {.name = "anconeus2", .muscle = "anconeus", .osim_name = "anconeus_2", .fmax = 9.792887327890158, .lceopt = 0.019785313041233297, .lslack = 0.0078357675410824935, .pennopt = 0.26179938779900003, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0015, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.0},
    {.name = "anconeus3", .muscle = "anconeus", .osim_name = "anconeus_3", .fmax = 3.4974597599607709, .lceopt = 0.02235367008741105, .lslack = 0.0042158237445555921, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00059999999999999995, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.0},
    {.name = "anconeus4", .muscle = "anconeus", .osim_name = "anconeus_4", .fmax = 16.508010067014837, .lceopt = 0.02619272825551059, .lslack = 0.029103031395011764, .pennopt = 0.31415926535900002, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0022000000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.0},
    {.name = "anconeus5", .muscle = "anconeus", .osim_name = "anconeus_5", .fmax = 16.508010067014837, .lceopt = 0.025898564333310854, .lslack = 0.019472604761887859, .pennopt = 0.401425727959, .vmax = 10.0, .tact = 0.012000004800001919, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0033300000000000001, .crosses_gh = 0, .dof_mask = 1, .max_activation = 0.0},
};

const int kMuscle0[1] = {0};
const int kMuscle1[2] = {1, 2};
const int kMuscle2[4] = {3, 4, 5, 6};
const int kMuscle3[5] = {7, 8, 9, 10, 11};
const int kMuscle4[7] = {12, 13, 14, 15, 16, 17, 18};
const int kMuscle5[3] = {19, 20, 21};
const int kMuscle6[2] = {22, 23};
const int kMuscle7[5] = {24, 25, 26, 27, 28};
const int kMuscle8[3] = {29, 30, 31};
const int kMuscle9[5] = {32, 33, 34, 35, 36};
const int kMuscle10[5] = {37, 38, 39, 40, 41};

const GroupDef kMuscles[11] = {
    {.name = "bicl", .num_elements = 1, .elements = kMuscle0},
    {.name = "bicb", .num_elements = 2, .elements = kMuscle1},
    {.name = "triclong", .num_elements = 4, .elements = kMuscle2},
    {.name = "tricmed", .num_elements = 5, .elements = kMuscle3},
    {.name = "brachialis", .num_elements = 7, .elements = kMuscle4},
    {.name = "brachiorad", .num_elements = 3, .elements = kMuscle5},
    {.name = "pronteres", .num_elements = 2, .elements = kMuscle6},
    {.name = "supinator", .num_elements = 5, .elements = kMuscle7},
    {.name = "pronquad", .num_elements = 3, .elements = kMuscle8},
    {.name = "triclat", .num_elements = 5, .elements = kMuscle9},
    {.name = "anconeus", .num_elements = 5, .elements = kMuscle10},
};

const int kGroup0[13] = {0, 1, 2, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21};
const int kGroup1[19] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41};
const int kGroup2[5] = {22, 23, 29, 30, 31};
const int kGroup3[5] = {24, 25, 26, 27, 28};
const int kGroup4[3] = {0, 1, 2};
const int kGroup5[14] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 32, 33, 34, 35, 36};

const GroupDef kGroups[6] = {
    {.name = "elbow_flexors", .num_elements = 13, .elements = kGroup0},
    {.name = "elbow_extensors", .num_elements = 19, .elements = kGroup1},
    {.name = "pronators", .num_elements = 5, .elements = kGroup2},
    {.name = "supinators", .num_elements = 5, .elements = kGroup3},
    {.name = "biceps", .num_elements = 3, .elements = kGroup4},
    {.name = "triceps", .num_elements = 14, .elements = kGroup5},
};

const char* const kBodyNames[4] = {"humerus", "ulna", "radius", "hand"};

const ModelDef kModel = {
    .name = "participant_A_FES",
    .source_hash = "a6b73006f7bd66708bb0af94f23a21910ada134588c9d0322f3a4473e2ebce21",
    .num_dofs = 2,
    .num_elements = 42,
    .dofs = kDofs,
    .elements = kElements,
    .num_muscles = 11,
    .muscles = kMuscles,
    .num_groups = 6,
    .groups = kGroups,
    .base_body = "scapula",
    .gravity_base = {1.9151805406858846, -9.4078806812419753, -1.9985616844601326},
    .base_rotation_in_thorax = {0.93779623202356455, 0.12184584092939058, 0.32510278105641355, -0.19529406481172315, 0.95933684604242786, 0.20379657522804756, -0.28705131153109059, -0.25461030394227263, 0.92345824901546281},
    .base_origin_in_thorax = {0.20346771515840928, 0.010903376262320115, 0.11569828084786157},
    .num_bodies = 4,
    .body_names = kBodyNames,
    .scapula_body = -1,
    .humerus_body = 0,
    .girdle = nullptr,
    .gh_centre = {0.0019292302570501929, -0.022102996186110207, -0.042267248431348436},
    .glenoid_normal = {-0.98162192074614485, 0.11772169614089467, 0.15019989004110462},
    .glenoid_major_axis = {0.11636734308752369, 0.99304662642683139, -0.017805594767928572},
    .glenoid_minor_axis = {-0.15125159891187798, 3.4694469519536142e-18, -0.98849529782725831},
    .rim_half_angle_major = 0.77440258910988402,
    .rim_half_angle_minor = 0.67282442664381403,
    .arm_mass = 6.4609553994725069,
    .passive_stiffness_inside = 1.0,
    .passive_stiffness_outside = 5000.0,
    .passive_damping = 1.0,
    .mass_matrix = &mass_matrix,
    .bias_force = &bias_force,
    .dynamics = &dynamics,
    .hand_position = &hand_position,
    .hand_jacobian = &hand_jacobian,
    .arm_momentum_rate = &arm_momentum_rate,
    .body_poses = &body_poses,
    .muscle_lengths = &muscle_lengths,
    .muscle_paths = &muscle_paths,
    .gh_directions = &gh_directions,
};

}  // namespace

const armrt::ModelDef& model_def() { return kModel; }

}  // namespace armrt::generated::participant_A_FES
