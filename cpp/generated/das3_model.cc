// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das3.json --out cpp/generated`
// from the model file das3.json (sha256 9289e81ac11b44228bbcac078e6e0a2af00fdbe2eabf7ee115c9eac3ffce5409).
// Change the model file or the generator and regenerate instead.

#include "das3.h"

namespace armrt::generated::das3 {

namespace {

const DofParams kDofs[11] = {
    {.name = "SCy", .osim_name = "SC_y", .range_min = -1.1345000000000001, .range_max = -0.28733061655785064, .rest = -0.37082035769742466},
    {.name = "SCz", .osim_name = "SC_z", .range_min = 0.071121780630944292, .range_max = 0.52359999999999995, .rest = 0.13179037522789691},
    {.name = "SCx", .osim_name = "SC_x", .range_min = 0.0, .range_max = 1.4486000000000001, .rest = 0.22272473343543234},
    {.name = "ACy", .osim_name = "AC_y", .range_min = 0.57599999999999996, .range_max = 1.2042999999999999, .rest = 0.62055303514435556},
    {.name = "ACz", .osim_name = "AC_z", .range_min = -0.47628612363264272, .range_max = 0.34910000000000002, .rest = -0.43528748346269519},
    {.name = "ACx", .osim_name = "AC_x", .range_min = -0.33011338189774653, .range_max = 0.31419999999999998, .rest = -0.31324137117457646},
    {.name = "GHy", .osim_name = "GH_y", .range_min = -0.10000000000000001, .range_max = 1.0, .rest = 0.43419629725225145},
    {.name = "GHz", .osim_name = "GH_z", .range_min = 0.25, .range_max = 1.4661, .rest = 0.49827547507556114},
    {.name = "GHyy", .osim_name = "GH_yy", .range_min = -0.25, .range_max = 0.80000000000000004, .rest = 0.27301239366601388},
    {.name = "ELx", .osim_name = "EL_x", .range_min = 0.087266460000000004, .range_max = 2.44346095, .rest = 0.65690320659830481},
    {.name = "PSy", .osim_name = "PS_y", .range_min = 0.087266460000000004, .range_max = 2.7925268000000001, .rest = 1.4214063526017877},
};

const ElementParams kElements[138] = {
    {.name = "trapscap1", .muscle = "trapscap", .osim_name = "trap_scap_1", .fmax = 118.0, .lceopt = 0.14460000000000001, .lslack = 0.01, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.019539999999999998, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap2", .muscle = "trapscap", .osim_name = "trap_scap_2", .fmax = 168.0, .lceopt = 0.11269999999999999, .lslack = 0.027, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.021610000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap3", .muscle = "trapscap", .osim_name = "trap_scap_3", .fmax = 199.0, .lceopt = 0.107, .lslack = 0.053999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.02419, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap4", .muscle = "trapscap", .osim_name = "trap_scap_4", .fmax = 138.0, .lceopt = 0.095200000000000007, .lslack = 0.052999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.01494, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap5", .muscle = "trapscap", .osim_name = "trap_scap_5", .fmax = 122.0, .lceopt = 0.092399999999999996, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.012800000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap6", .muscle = "trapscap", .osim_name = "trap_scap_6", .fmax = 101.0, .lceopt = 0.089300000000000004, .lslack = 0.033000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.01025, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap7", .muscle = "trapscap", .osim_name = "trap_scap_7", .fmax = 97.0, .lceopt = 0.086800000000000002, .lslack = 0.035999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.00958, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap8", .muscle = "trapscap", .osim_name = "trap_scap_8", .fmax = 138.0, .lceopt = 0.076999999999999999, .lslack = 0.048000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.012120000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap9", .muscle = "trapscap", .osim_name = "trap_scap_9", .fmax = 123.0, .lceopt = 0.1011, .lslack = 0.034000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.014160000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap10", .muscle = "trapscap", .osim_name = "trap_scap10", .fmax = 81.0, .lceopt = 0.12640000000000001, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.01158, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapscap11", .muscle = "trapscap", .osim_name = "trap_scap11", .fmax = 92.0, .lceopt = 0.13550000000000001, .lslack = 0.031, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.014069999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "trapclav1", .muscle = "trapclav", .osim_name = "trap_clav_1", .fmax = 97.0, .lceopt = 0.1547, .lslack = 0.047, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014399998848000091, .tdeact = 0.053499996522500225, .peeslack = 1.0, .mass = 0.01712, .crosses_gh = 0, .dof_mask = 7, .max_activation = 1.0},
    {.name = "trapclav2", .muscle = "trapclav", .osim_name = "trap_clav_2", .fmax = 47.0, .lceopt = 0.16800000000000001, .lslack = 0.042000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.0096900000000000007, .crosses_gh = 0, .dof_mask = 7, .max_activation = 1.0},
    {.name = "levscap1", .muscle = "levscap", .osim_name = "lev_scap_1", .fmax = 96.0, .lceopt = 0.1578, .lslack = 0.019, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.017309999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "levscap2", .muscle = "levscap", .osim_name = "lev_scap_2", .fmax = 104.0, .lceopt = 0.13020000000000001, .lslack = 0.017999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.015440000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "pectmin1", .muscle = "pectmin", .osim_name = "pect_min_1", .fmax = 47.0, .lceopt = 0.076499999999999999, .lslack = 0.050999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014999999250000038, .tdeact = 0.054999994500000558, .peeslack = 1.0, .mass = 0.0040699999999999998, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "pectmin2", .muscle = "pectmin", .osim_name = "pect_min_2", .fmax = 107.0, .lceopt = 0.1086, .lslack = 0.041000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014999999250000038, .tdeact = 0.054999994500000558, .peeslack = 1.0, .mass = 0.01323, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "pectmin3", .muscle = "pectmin", .osim_name = "pect_min_3", .fmax = 107.0, .lceopt = 0.1075, .lslack = 0.029000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014999999250000038, .tdeact = 0.054999994500000558, .peeslack = 1.0, .mass = 0.01303, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "pectmin4", .muscle = "pectmin", .osim_name = "pect_min_4", .fmax = 46.0, .lceopt = 0.1381, .lslack = 0.025999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.014999999250000038, .tdeact = 0.054999994500000558, .peeslack = 1.0, .mass = 0.0071999999999999998, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "rhomboid1", .muscle = "rhomboid", .osim_name = "rhomboid_1", .fmax = 51.0, .lceopt = 0.098599999999999993, .lslack = 0.014999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0083999999328000004, .tdeact = 0.038499994032500928, .peeslack = 1.0, .mass = 0.0057499999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "rhomboid2", .muscle = "rhomboid", .osim_name = "rhomboid_2", .fmax = 92.0, .lceopt = 0.1077, .lslack = 0.066000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0083999999328000004, .tdeact = 0.038499994032500928, .peeslack = 1.0, .mass = 0.011299999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "rhomboid3", .muscle = "rhomboid", .osim_name = "rhomboid_3", .fmax = 142.0, .lceopt = 0.12590000000000001, .lslack = 0.032000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0083999999328000004, .tdeact = 0.038499994032500928, .peeslack = 1.0, .mass = 0.02034, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "rhomboid4", .muscle = "rhomboid", .osim_name = "rhomboid_4", .fmax = 82.0, .lceopt = 0.12670000000000001, .lslack = 0.031, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.01176, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "rhomboid5", .muscle = "rhomboid", .osim_name = "rhomboid_5", .fmax = 67.0, .lceopt = 0.11700000000000001, .lslack = 0.040000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.0088500000000000002, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant1", .muscle = "serrant", .osim_name = "serr_ant_1", .fmax = 61.0, .lceopt = 0.16350000000000001, .lslack = 0.025000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.011390000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant2", .muscle = "serrant", .osim_name = "serr_ant_2", .fmax = 110.0, .lceopt = 0.16669999999999999, .lslack = 0.0089999999999999993, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.020830000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant3", .muscle = "serrant", .osim_name = "serr_ant_3", .fmax = 105.0, .lceopt = 0.16220000000000001, .lslack = 0.007000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.01925, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant4", .muscle = "serrant", .osim_name = "serr_ant_4", .fmax = 110.0, .lceopt = 0.12889999999999999, .lslack = 0.010999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0069000002967000134, .tdeact = 0.034700004580400609, .peeslack = 1.0, .mass = 0.016289999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant5", .muscle = "serrant", .osim_name = "serr_ant_5", .fmax = 64.0, .lceopt = 0.12590000000000001, .lslack = 0.010999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0090899999999999991, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant6", .muscle = "serrant", .osim_name = "serr_ant_6", .fmax = 97.0, .lceopt = 0.122, .lslack = 0.010999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.01345, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant7", .muscle = "serrant", .osim_name = "serr_ant_7", .fmax = 47.0, .lceopt = 0.1133, .lslack = 0.0089999999999999993, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0060899999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant8", .muscle = "serrant", .osim_name = "serr_ant_8", .fmax = 76.0, .lceopt = 0.084500000000000006, .lslack = 0.010999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0072900000000000005, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant9", .muscle = "serrant", .osim_name = "serr_ant_9", .fmax = 79.0, .lceopt = 0.080000000000000002, .lslack = 0.007000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0072400000000000008, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant10", .muscle = "serrant", .osim_name = "serr_ant10", .fmax = 63.0, .lceopt = 0.066000000000000003, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0047600000000000003, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant11", .muscle = "serrant", .osim_name = "serr_ant11", .fmax = 23.0, .lceopt = 0.088499999999999995, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0022899999999999999, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "serrant12", .muscle = "serrant", .osim_name = "serr_ant12", .fmax = 112.0, .lceopt = 0.094500000000000001, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.012120000000000001, .crosses_gh = 0, .dof_mask = 63, .max_activation = 1.0},
    {.name = "deltscap1", .muscle = "deltscap", .osim_name = "delt_scap_1", .fmax = 289.0, .lceopt = 0.1128, .lslack = 0.080000000000000002, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.03703, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap2", .muscle = "deltscap", .osim_name = "delt_scap_2", .fmax = 211.0, .lceopt = 0.094899999999999998, .lslack = 0.075999999999999998, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.022689999999999998, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap3", .muscle = "deltscap", .osim_name = "delt_scap_3", .fmax = 446.0, .lceopt = 0.083299999999999999, .lslack = 0.062, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.042139999999999997, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap4", .muscle = "deltscap", .osim_name = "delt_scap_4", .fmax = 117.0, .lceopt = 0.066600000000000006, .lslack = 0.044999999999999998, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0088800000000000007, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap5", .muscle = "deltscap", .osim_name = "delt_scap_5", .fmax = 120.0, .lceopt = 0.065600000000000006, .lslack = 0.035000000000000003, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.0089099999999999995, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap6", .muscle = "deltscap", .osim_name = "delt_scap_6", .fmax = 285.0, .lceopt = 0.076700000000000004, .lslack = 0.067000000000000004, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.024850000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap7", .muscle = "deltscap", .osim_name = "delt_scap_7", .fmax = 149.0, .lceopt = 0.075399999999999995, .lslack = 0.082000000000000003, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.012749999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap8", .muscle = "deltscap", .osim_name = "delt_scap_8", .fmax = 215.0, .lceopt = 0.070999999999999994, .lslack = 0.065000000000000002, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.017299999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap9", .muscle = "deltscap", .osim_name = "delt_scap_9", .fmax = 286.0, .lceopt = 0.073200000000000001, .lslack = 0.070999999999999994, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.023779999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap10", .muscle = "deltscap", .osim_name = "delt_scap10", .fmax = 445.0, .lceopt = 0.074800000000000005, .lslack = 0.064000000000000001, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.037900000000000003, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltscap11", .muscle = "deltscap", .osim_name = "delt_scap11", .fmax = 239.0, .lceopt = 0.073700000000000002, .lslack = 0.048000000000000001, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.020119999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "deltclav1", .muscle = "deltclav", .osim_name = "delt_clav_1", .fmax = 128.0, .lceopt = 0.083599999999999994, .lslack = 0.062, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.01217, .crosses_gh = 1, .dof_mask = 504, .max_activation = 1.0},
    {.name = "deltclav2", .muscle = "deltclav", .osim_name = "delt_clav_2", .fmax = 160.0, .lceopt = 0.094, .lslack = 0.087999999999999995, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.017010000000000001, .crosses_gh = 1, .dof_mask = 504, .max_activation = 1.0},
    {.name = "deltclav3", .muscle = "deltclav", .osim_name = "delt_clav_3", .fmax = 105.0, .lceopt = 0.082400000000000001, .lslack = 0.067000000000000004, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.0098300000000000002, .crosses_gh = 1, .dof_mask = 504, .max_activation = 1.0},
    {.name = "deltclav4", .muscle = "deltclav", .osim_name = "delt_clav_4", .fmax = 112.0, .lceopt = 0.099099999999999994, .lslack = 0.072999999999999995, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.01259, .crosses_gh = 1, .dof_mask = 504, .max_activation = 1.0},
    {.name = "coracobr1", .muscle = "coracobr", .osim_name = "coracobr_1", .fmax = 201.0, .lceopt = 0.066000000000000003, .lslack = 0.091999999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.01506, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "coracobr2", .muscle = "coracobr", .osim_name = "coracobr_2", .fmax = 148.0, .lceopt = 0.0683, .lslack = 0.104, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.011509999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "coracobr3", .muscle = "coracobr", .osim_name = "coracobr_3", .fmax = 114.0, .lceopt = 0.072700000000000001, .lslack = 0.113, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.009389999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "infra1", .muscle = "infra", .osim_name = "infra_1", .fmax = 272.0, .lceopt = 0.063299999999999995, .lslack = 0.037999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.019609999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "infra2", .muscle = "infra", .osim_name = "infra_2", .fmax = 275.0, .lceopt = 0.071900000000000006, .lslack = 0.107, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.022450000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "infra3", .muscle = "infra", .osim_name = "infra_3", .fmax = 194.0, .lceopt = 0.067699999999999996, .lslack = 0.084000000000000005, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.014880000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "infra4", .muscle = "infra", .osim_name = "infra_4", .fmax = 207.0, .lceopt = 0.0693, .lslack = 0.070999999999999994, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.1000000000000001, .mass = 0.016310000000000002, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "infra5", .muscle = "infra", .osim_name = "infra_5", .fmax = 302.0, .lceopt = 0.069800000000000001, .lslack = 0.050000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.2, .mass = 0.024140000000000002, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "infra6", .muscle = "infra", .osim_name = "infra_6", .fmax = 182.0, .lceopt = 0.075300000000000006, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.1000000000000001, .mass = 0.015640000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termin1", .muscle = "termin", .osim_name = "ter_min_1", .fmax = 122.0, .lceopt = 0.050099999999999999, .lslack = 0.049000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.3, .mass = 0.0071400000000000005, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termin2", .muscle = "termin", .osim_name = "ter_min_2", .fmax = 195.0, .lceopt = 0.055, .lslack = 0.050999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.3999999999999999, .mass = 0.01221, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termin3", .muscle = "termin", .osim_name = "ter_min_3", .fmax = 180.0, .lceopt = 0.050599999999999999, .lslack = 0.017999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.3999999999999999, .mass = 0.010410000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termaj1", .muscle = "termaj", .osim_name = "ter_maj_1", .fmax = 165.0, .lceopt = 0.1411, .lslack = 0.0060000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.0, .mass = 0.026429999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termaj2", .muscle = "termaj", .osim_name = "ter_maj_2", .fmax = 85.0, .lceopt = 0.1595, .lslack = 0.012, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.01549, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termaj3", .muscle = "termaj", .osim_name = "ter_maj_3", .fmax = 200.0, .lceopt = 0.15260000000000001, .lslack = 0.014999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.034810000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "termaj4", .muscle = "termaj", .osim_name = "ter_maj_4", .fmax = 158.0, .lceopt = 0.10929999999999999, .lslack = 0.034000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.019709999999999998, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "supra1", .muscle = "supra", .osim_name = "supra_1", .fmax = 120.0, .lceopt = 0.054100000000000002, .lslack = 0.017000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.1000000000000001, .mass = 0.0073999999999999995, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "supra2", .muscle = "supra", .osim_name = "supra_2", .fmax = 113.0, .lceopt = 0.0591, .lslack = 0.025000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.0075599999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "supra3", .muscle = "supra", .osim_name = "supra_3", .fmax = 258.0, .lceopt = 0.056399999999999999, .lslack = 0.051999999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.01651, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "supra4", .muscle = "supra", .osim_name = "supra_4", .fmax = 130.0, .lceopt = 0.055399999999999998, .lslack = 0.031, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.0081899999999999994, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap1", .muscle = "subscap", .osim_name = "subscap_1", .fmax = 44.0, .lceopt = 0.055599999999999997, .lslack = 0.028000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.00281, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap2", .muscle = "subscap", .osim_name = "subscap_2", .fmax = 78.0, .lceopt = 0.064899999999999999, .lslack = 0.043999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.0057499999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap3", .muscle = "subscap", .osim_name = "subscap_3", .fmax = 264.0, .lceopt = 0.067599999999999993, .lslack = 0.058999999999999997, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.020209999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap4", .muscle = "subscap", .osim_name = "subscap_4", .fmax = 274.0, .lceopt = 0.074399999999999994, .lslack = 0.055, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.02376, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap5", .muscle = "subscap", .osim_name = "subscap_5", .fmax = 114.0, .lceopt = 0.079699999999999993, .lslack = 0.066000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.010330000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap6", .muscle = "subscap", .osim_name = "subscap_6", .fmax = 149.0, .lceopt = 0.076200000000000004, .lslack = 0.076999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.012919999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap7", .muscle = "subscap", .osim_name = "subscap_7", .fmax = 162.0, .lceopt = 0.082000000000000003, .lslack = 0.079000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.015129999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap8", .muscle = "subscap", .osim_name = "subscap_8", .fmax = 61.0, .lceopt = 0.076499999999999999, .lslack = 0.040000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.0053200000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap9", .muscle = "subscap", .osim_name = "subscap_9", .fmax = 222.0, .lceopt = 0.072099999999999997, .lslack = 0.058999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.018200000000000001, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap10", .muscle = "subscap", .osim_name = "subscap10", .fmax = 47.0, .lceopt = 0.067599999999999993, .lslack = 0.01, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.0036099999999999999, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "subscap11", .muscle = "subscap", .osim_name = "subscap11", .fmax = 16.0, .lceopt = 0.064299999999999996, .lslack = 0.01, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.00115, .crosses_gh = 1, .dof_mask = 448, .max_activation = 1.0},
    {.name = "bicl", .muscle = "bicl", .osim_name = "bic_l", .fmax = 347.0, .lceopt = 0.12920000000000001, .lslack = 0.23350000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.3, .mass = 0.066199999999999995, .crosses_gh = 1, .dof_mask = 1984, .max_activation = 1.0},
    {.name = "bicb1", .muscle = "bicb", .osim_name = "bic_b_1", .fmax = 173.0, .lceopt = 0.11700000000000001, .lslack = 0.1913, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.5, .mass = 0.020789999999999999, .crosses_gh = 1, .dof_mask = 1984, .max_activation = 1.0},
    {.name = "bicb2", .muscle = "bicb", .osim_name = "bic_b_2", .fmax = 322.0, .lceopt = 0.1149, .lslack = 0.19270000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.6000000000000001, .mass = 0.03107, .crosses_gh = 1, .dof_mask = 1984, .max_activation = 1.0},
    {.name = "triclong1", .muscle = "triclong", .osim_name = "tric_long_1", .fmax = 223.0, .lceopt = 0.1008, .lslack = 0.2041, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.5, .mass = 0.026970000000000001, .crosses_gh = 1, .dof_mask = 960, .max_activation = 1.0},
    {.name = "triclong2", .muscle = "triclong", .osim_name = "tric_long_2", .fmax = 296.0, .lceopt = 0.088099999999999998, .lslack = 0.21929999999999999, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.5, .mass = 0.02955, .crosses_gh = 1, .dof_mask = 960, .max_activation = 1.0},
    {.name = "triclong3", .muscle = "triclong", .osim_name = "tric_long_3", .fmax = 283.0, .lceopt = 0.1183, .lslack = 0.218, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.02964, .crosses_gh = 1, .dof_mask = 960, .max_activation = 1.0},
    {.name = "triclong4", .muscle = "triclong", .osim_name = "tric_long_4", .fmax = 327.0, .lceopt = 0.1226, .lslack = 0.21970000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.032030000000000003, .crosses_gh = 1, .dof_mask = 960, .max_activation = 1.0},
    {.name = "latdorsi1", .muscle = "latdorsi", .osim_name = "lat_dorsi_1", .fmax = 56.0, .lceopt = 0.23430000000000001, .lslack = 0.089999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.01498, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "latdorsi2", .muscle = "latdorsi", .osim_name = "lat_dorsi_2", .fmax = 88.0, .lceopt = 0.28570000000000001, .lslack = 0.083000000000000004, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.028830000000000001, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "latdorsi3", .muscle = "latdorsi", .osim_name = "lat_dorsi_3", .fmax = 129.0, .lceopt = 0.29509999999999997, .lslack = 0.105, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.043049999999999998, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "latdorsi4", .muscle = "latdorsi", .osim_name = "lat_dorsi_4", .fmax = 96.0, .lceopt = 0.3206, .lslack = 0.12, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.035150000000000001, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "latdorsi5", .muscle = "latdorsi", .osim_name = "lat_dorsi_5", .fmax = 88.0, .lceopt = 0.31290000000000001, .lslack = 0.071999999999999995, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.031570000000000001, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "latdorsi6", .muscle = "latdorsi", .osim_name = "lat_dorsi_6", .fmax = 105.0, .lceopt = 0.3402, .lslack = 0.069000000000000006, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.040689999999999997, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajt1", .muscle = "pectmajt", .osim_name = "pect_maj_t_1", .fmax = 125.0, .lceopt = 0.18840000000000001, .lslack = 0.035999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.026919999999999999, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajt2", .muscle = "pectmajt", .osim_name = "pect_maj_t_2", .fmax = 118.0, .lceopt = 0.183, .lslack = 0.042999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.024479999999999998, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajt3", .muscle = "pectmajt", .osim_name = "pect_maj_t_3", .fmax = 165.0, .lceopt = 0.18529999999999999, .lslack = 0.052999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.034750000000000003, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajt4", .muscle = "pectmajt", .osim_name = "pect_maj_t_4", .fmax = 157.0, .lceopt = 0.18329999999999999, .lslack = 0.028000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.033009999999999998, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajt5", .muscle = "pectmajt", .osim_name = "pect_maj_t_5", .fmax = 133.0, .lceopt = 0.14999999999999999, .lslack = 0.025999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.02273, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajt6", .muscle = "pectmajt", .osim_name = "pect_maj_t_6", .fmax = 198.0, .lceopt = 0.1449, .lslack = 0.035999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.03243, .crosses_gh = 1, .dof_mask = 511, .max_activation = 1.0},
    {.name = "pectmajc1", .muscle = "pectmajc", .osim_name = "pect_maj_c_1", .fmax = 179.0, .lceopt = 0.1363, .lslack = 0.017000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.027689999999999999, .crosses_gh = 1, .dof_mask = 504, .max_activation = 1.0},
    {.name = "pectmajc2", .muscle = "pectmajc", .osim_name = "pect_maj_c_2", .fmax = 113.0, .lceopt = 0.1091, .lslack = 0.014, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.013990000000000001, .crosses_gh = 1, .dof_mask = 504, .max_activation = 1.0},
    {.name = "tricmed1", .muscle = "tricmed", .osim_name = "tric_med_1", .fmax = 263.0, .lceopt = 0.080699999999999994, .lslack = 0.087499999999999994, .pennopt = 0.29670597283900002, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.3, .mass = 0.0184, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "tricmed2", .muscle = "tricmed", .osim_name = "tric_med_2", .fmax = 256.0, .lceopt = 0.077299999999999994, .lslack = 0.11219999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.017649999999999999, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "tricmed3", .muscle = "tricmed", .osim_name = "tric_med_3", .fmax = 240.0, .lceopt = 0.060199999999999997, .lslack = 0.010699999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.011950000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "tricmed4", .muscle = "tricmed", .osim_name = "tric_med_4", .fmax = 211.0, .lceopt = 0.0746, .lslack = 0.040399999999999998, .pennopt = 0.13962634016, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.013950000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "tricmed5", .muscle = "tricmed", .osim_name = "tric_med_5", .fmax = 107.0, .lceopt = 0.080699999999999994, .lslack = 0.073800000000000004, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0077000000000000002, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis1", .muscle = "brachialis", .osim_name = "brachialis_1", .fmax = 314.0, .lceopt = 0.087599999999999997, .lslack = 0.080699999999999994, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.029100000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis2", .muscle = "brachialis", .osim_name = "brachialis_2", .fmax = 158.0, .lceopt = 0.095299999999999996, .lslack = 0.059200000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.015900000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis3", .muscle = "brachialis", .osim_name = "brachialis_3", .fmax = 157.0, .lceopt = 0.086999999999999994, .lslack = 0.039399999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.1000000000000001, .mass = 0.01465, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis4", .muscle = "brachialis", .osim_name = "brachialis_4", .fmax = 87.0, .lceopt = 0.075800000000000006, .lslack = 0.031699999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.007000000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis5", .muscle = "brachialis", .osim_name = "brachialis_5", .fmax = 101.0, .lceopt = 0.061899999999999997, .lslack = 0.020899999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0066, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis6", .muscle = "brachialis", .osim_name = "brachialis_6", .fmax = 104.0, .lceopt = 0.047199999999999999, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0041000000000000003, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachialis7", .muscle = "brachialis", .osim_name = "brachialis_7", .fmax = 118.0, .lceopt = 0.062100000000000002, .lslack = 0.0076, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0065000000000000006, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "brachiorad1", .muscle = "brachiorad", .osim_name = "brachiorad_1", .fmax = 30.0, .lceopt = 0.1613, .lslack = 0.1197, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0047000000000000002, .crosses_gh = 0, .dof_mask = 1536, .max_activation = 1.0},
    {.name = "brachiorad2", .muscle = "brachiorad", .osim_name = "brachiorad_2", .fmax = 82.0, .lceopt = 0.1613, .lslack = 0.1197, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.014, .crosses_gh = 0, .dof_mask = 1536, .max_activation = 1.0},
    {.name = "brachiorad3", .muscle = "brachiorad", .osim_name = "brachiorad_3", .fmax = 52.0, .lceopt = 0.1066, .lslack = 0.1542, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0059700000000000005, .crosses_gh = 0, .dof_mask = 1536, .max_activation = 1.0},
    {.name = "pronteres1", .muscle = "pronteres", .osim_name = "pron_teres_1", .fmax = 510.0, .lceopt = 0.060999999999999999, .lslack = 0.085099999999999995, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0275, .crosses_gh = 0, .dof_mask = 1536, .max_activation = 1.0},
    {.name = "pronteres2", .muscle = "pronteres", .osim_name = "pron_teres_2", .fmax = 141.0, .lceopt = 0.039100000000000003, .lslack = 0.048399999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0043299999999999996, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "supinator1", .muscle = "supinator", .osim_name = "supinator_1", .fmax = 47.0, .lceopt = 0.026700000000000002, .lslack = 0.025399999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00084000000000000014, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "supinator2", .muscle = "supinator", .osim_name = "supinator_2", .fmax = 232.0, .lceopt = 0.025999999999999999, .lslack = 0.023099999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.00364, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "supinator3", .muscle = "supinator", .osim_name = "supinator_3", .fmax = 126.0, .lceopt = 0.0252, .lslack = 0.014999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0033599999999999997, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "supinator4", .muscle = "supinator", .osim_name = "supinator_4", .fmax = 148.0, .lceopt = 0.0263, .lslack = 0.014500000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.00296, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "supinator5", .muscle = "supinator", .osim_name = "supinator_5", .fmax = 285.0, .lceopt = 0.027400000000000001, .lslack = 0.013899999999999999, .pennopt = 0.03490658504, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0067599999999999995, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "pronquad1", .muscle = "pronquad", .osim_name = "pron_quad_1", .fmax = 73.0, .lceopt = 0.037699999999999997, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.1000000000000001, .mass = 0.0016299999999999999, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "pronquad2", .muscle = "pronquad", .osim_name = "pron_quad_2", .fmax = 178.0, .lceopt = 0.038600000000000002, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00347, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "pronquad3", .muscle = "pronquad", .osim_name = "pron_quad_3", .fmax = 219.0, .lceopt = 0.035200000000000002, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0049299999999999995, .crosses_gh = 0, .dof_mask = 1024, .max_activation = 1.0},
    {.name = "triclat1", .muscle = "triclat", .osim_name = "tric_lat_1", .fmax = 153.0, .lceopt = 0.075800000000000006, .lslack = 0.17069999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.012500000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "triclat2", .muscle = "triclat", .osim_name = "tric_lat_2", .fmax = 410.0, .lceopt = 0.076600000000000001, .lslack = 0.17699999999999999, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0332, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "triclat3", .muscle = "triclat", .osim_name = "tric_lat_3", .fmax = 219.0, .lceopt = 0.065600000000000006, .lslack = 0.19109999999999999, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0152, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "triclat4", .muscle = "triclat", .osim_name = "tric_lat_4", .fmax = 275.0, .lceopt = 0.063799999999999996, .lslack = 0.157, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.016199999999999999, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "triclat5", .muscle = "triclat", .osim_name = "tric_lat_5", .fmax = 87.0, .lceopt = 0.063799999999999996, .lslack = 0.157, .pennopt = 0.29670597283900002, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0058500000000000002, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "anconeus1", .muscle = "anconeus", .osim_name = "anconeus_1", .fmax = 31.0, .lceopt = 0.0252, .lslack = 0.0064000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00083000000000000001, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "anconeus2", .muscle = "anconeus", .osim_name = "anconeus_2", .fmax = 70.0, .lceopt = 0.020199999999999999, .lslack = 0.0080000000000000002, .pennopt = 0.26179938779900003, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0015, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "anconeus3", .muscle = "anconeus", .osim_name = "anconeus_3", .fmax = 25.0, .lceopt = 0.022800000000000001, .lslack = 0.0043, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00060000000000000006, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "anconeus4", .muscle = "anconeus", .osim_name = "anconeus_4", .fmax = 118.0, .lceopt = 0.027, .lslack = 0.029999999999999999, .pennopt = 0.31415926535900002, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0021999999999999997, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
    {.name = "anconeus5", .muscle = "anconeus", .osim_name = "anconeus_5", .fmax = 118.0, .lceopt = 0.026599999999999999, .lslack = 0.02, .pennopt = 0.401425727959, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0033300000000000005, .crosses_gh = 0, .dof_mask = 512, .max_activation = 1.0},
};

const int kMuscle0[11] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
const int kMuscle1[2] = {11, 12};
const int kMuscle2[2] = {13, 14};
const int kMuscle3[4] = {15, 16, 17, 18};
const int kMuscle4[5] = {19, 20, 21, 22, 23};
const int kMuscle5[12] = {24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35};
const int kMuscle6[11] = {36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46};
const int kMuscle7[4] = {47, 48, 49, 50};
const int kMuscle8[3] = {51, 52, 53};
const int kMuscle9[6] = {54, 55, 56, 57, 58, 59};
const int kMuscle10[3] = {60, 61, 62};
const int kMuscle11[4] = {63, 64, 65, 66};
const int kMuscle12[4] = {67, 68, 69, 70};
const int kMuscle13[11] = {71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81};
const int kMuscle14[1] = {82};
const int kMuscle15[2] = {83, 84};
const int kMuscle16[4] = {85, 86, 87, 88};
const int kMuscle17[6] = {89, 90, 91, 92, 93, 94};
const int kMuscle18[6] = {95, 96, 97, 98, 99, 100};
const int kMuscle19[2] = {101, 102};
const int kMuscle20[5] = {103, 104, 105, 106, 107};
const int kMuscle21[7] = {108, 109, 110, 111, 112, 113, 114};
const int kMuscle22[3] = {115, 116, 117};
const int kMuscle23[2] = {118, 119};
const int kMuscle24[5] = {120, 121, 122, 123, 124};
const int kMuscle25[3] = {125, 126, 127};
const int kMuscle26[5] = {128, 129, 130, 131, 132};
const int kMuscle27[5] = {133, 134, 135, 136, 137};

const GroupDef kMuscles[28] = {
    {.name = "trapscap", .num_elements = 11, .elements = kMuscle0},
    {.name = "trapclav", .num_elements = 2, .elements = kMuscle1},
    {.name = "levscap", .num_elements = 2, .elements = kMuscle2},
    {.name = "pectmin", .num_elements = 4, .elements = kMuscle3},
    {.name = "rhomboid", .num_elements = 5, .elements = kMuscle4},
    {.name = "serrant", .num_elements = 12, .elements = kMuscle5},
    {.name = "deltscap", .num_elements = 11, .elements = kMuscle6},
    {.name = "deltclav", .num_elements = 4, .elements = kMuscle7},
    {.name = "coracobr", .num_elements = 3, .elements = kMuscle8},
    {.name = "infra", .num_elements = 6, .elements = kMuscle9},
    {.name = "termin", .num_elements = 3, .elements = kMuscle10},
    {.name = "termaj", .num_elements = 4, .elements = kMuscle11},
    {.name = "supra", .num_elements = 4, .elements = kMuscle12},
    {.name = "subscap", .num_elements = 11, .elements = kMuscle13},
    {.name = "bicl", .num_elements = 1, .elements = kMuscle14},
    {.name = "bicb", .num_elements = 2, .elements = kMuscle15},
    {.name = "triclong", .num_elements = 4, .elements = kMuscle16},
    {.name = "latdorsi", .num_elements = 6, .elements = kMuscle17},
    {.name = "pectmajt", .num_elements = 6, .elements = kMuscle18},
    {.name = "pectmajc", .num_elements = 2, .elements = kMuscle19},
    {.name = "tricmed", .num_elements = 5, .elements = kMuscle20},
    {.name = "brachialis", .num_elements = 7, .elements = kMuscle21},
    {.name = "brachiorad", .num_elements = 3, .elements = kMuscle22},
    {.name = "pronteres", .num_elements = 2, .elements = kMuscle23},
    {.name = "supinator", .num_elements = 5, .elements = kMuscle24},
    {.name = "pronquad", .num_elements = 3, .elements = kMuscle25},
    {.name = "triclat", .num_elements = 5, .elements = kMuscle26},
    {.name = "anconeus", .num_elements = 5, .elements = kMuscle27},
};

const int kGroup0[24] = {54, 55, 56, 57, 58, 59, 60, 61, 62, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81};
const int kGroup1[15] = {36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50};
const int kGroup2[13] = {82, 83, 84, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117};
const int kGroup3[19] = {85, 86, 87, 88, 103, 104, 105, 106, 107, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137};
const int kGroup4[5] = {118, 119, 125, 126, 127};
const int kGroup5[5] = {120, 121, 122, 123, 124};
const int kGroup6[3] = {82, 83, 84};
const int kGroup7[14] = {85, 86, 87, 88, 103, 104, 105, 106, 107, 128, 129, 130, 131, 132};
const int kGroup8[8] = {95, 96, 97, 98, 99, 100, 101, 102};
const int kGroup9[13] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
const int kGroup10[12] = {24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35};
const int kGroup11[5] = {19, 20, 21, 22, 23};
const int kGroup12[2] = {13, 14};
const int kGroup13[4] = {15, 16, 17, 18};
const int kGroup14[36] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35};

const GroupDef kGroups[15] = {
    {.name = "rotator_cuff", .num_elements = 24, .elements = kGroup0},
    {.name = "deltoid", .num_elements = 15, .elements = kGroup1},
    {.name = "elbow_flexors", .num_elements = 13, .elements = kGroup2},
    {.name = "elbow_extensors", .num_elements = 19, .elements = kGroup3},
    {.name = "pronators", .num_elements = 5, .elements = kGroup4},
    {.name = "supinators", .num_elements = 5, .elements = kGroup5},
    {.name = "biceps", .num_elements = 3, .elements = kGroup6},
    {.name = "triceps", .num_elements = 14, .elements = kGroup7},
    {.name = "pectoralis_major", .num_elements = 8, .elements = kGroup8},
    {.name = "trapezius", .num_elements = 13, .elements = kGroup9},
    {.name = "serratus_anterior", .num_elements = 12, .elements = kGroup10},
    {.name = "rhomboids", .num_elements = 5, .elements = kGroup11},
    {.name = "levator_scapulae", .num_elements = 2, .elements = kGroup12},
    {.name = "pectoralis_minor", .num_elements = 4, .elements = kGroup13},
    {.name = "scapular", .num_elements = 36, .elements = kGroup14},
};

const char* const kBodyNames[6] = {"clavicle", "scapula", "humerus", "ulna", "radius", "hand"};
const char* const kContactPointNames[2] = {"TS", "AI"};

const GirdleDef kGirdle = {
    .thorax = {.centre = {0.0, -0.14860000000000001, 0.0591}, .radii = {0.14699999999999999, 0.2079, 0.094399999999999998}, .k = 20000.0, .eps = 0.01},
    .num_contact_points = 2,
    .contact_point_names = kContactPointNames,
    .conoid = {.origin = {0.13650000000000001, 0.0206, 0.013599999999999999}, .insertion = {-0.053600000000000002, -0.00089999999999999998, -0.026599999999999999}, .length = 0.017399999999999999, .stiffness = 80000.0, .eps = 0.001},
    .points = &girdle_points,
};

const ModelDef kModel = {
    .name = "das3",
    .source_hash = "9289e81ac11b44228bbcac078e6e0a2af00fdbe2eabf7ee115c9eac3ffce5409",
    .num_dofs = 11,
    .num_elements = 138,
    .dofs = kDofs,
    .elements = kElements,
    .num_muscles = 28,
    .muscles = kMuscles,
    .num_groups = 15,
    .groups = kGroups,
    .base_body = "thorax",
    .gravity_base = {0.0, -9.8066499999999994, 0.0},
    .base_rotation_in_thorax = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0},
    .base_origin_in_thorax = {0.0, 0.0, 0.0},
    .num_bodies = 6,
    .body_names = kBodyNames,
    .scapula_body = 1,
    .humerus_body = 2,
    .girdle = &kGirdle,
    .gh_centre = {0.002, -0.023, -0.043900000000000002},
    .glenoid_normal = {-0.98162192074614485, 0.11772169614089467, 0.15019989004110462},
    .glenoid_major_axis = {0.11636734308752369, 0.99304662642683139, -0.017805594767928572},
    .glenoid_minor_axis = {-0.15125159891187798, 3.4694469519536142e-18, -0.98849529782725831},
    .rim_half_angle_major = 0.77440258910988402,
    .rim_half_angle_minor = 0.67282442664381403,
    .arm_mass = 3.6696999999999997,
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

}  // namespace armrt::generated::das3
