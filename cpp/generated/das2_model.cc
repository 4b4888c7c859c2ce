// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das2.json --out cpp/generated`
// from the model file das2.json (sha256 effb6ef66ec79560b06b1541ad3764787289ecb15b03c0a146d0090edd57a0b0).
// Change the model file or the generator and regenerate instead.

#include "das2.h"

namespace armrt::generated::das2 {

namespace {

const DofParams kDofs[5] = {
    {.name = "GHy", .osim_name = "GH_y", .range_min = -0.10000000000000001, .range_max = 1.0, .rest = 0.43419629725225145},
    {.name = "GHz", .osim_name = "GH_z", .range_min = 0.25, .range_max = 1.4661, .rest = 0.49827547507556114},
    {.name = "GHyy", .osim_name = "GH_yy", .range_min = -0.25, .range_max = 0.80000000000000004, .rest = 0.27301239366601388},
    {.name = "ELx", .osim_name = "EL_x", .range_min = 0.087266460000000004, .range_max = 2.44346095, .rest = 0.65690320659830481},
    {.name = "PSy", .osim_name = "PS_y", .range_min = 0.087266460000000004, .range_max = 2.7925268000000001, .rest = 1.4214063526017877},
};

const ElementParams kElements[102] = {
    {.name = "deltscap1", .muscle = "deltscap", .osim_name = "delt_scap_1", .fmax = 289.0, .lceopt = 0.1128, .lslack = 0.080000000000000002, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.03703, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap2", .muscle = "deltscap", .osim_name = "delt_scap_2", .fmax = 211.0, .lceopt = 0.094899999999999998, .lslack = 0.075999999999999998, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.022689999999999998, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap3", .muscle = "deltscap", .osim_name = "delt_scap_3", .fmax = 446.0, .lceopt = 0.083299999999999999, .lslack = 0.062, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.042139999999999997, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap4", .muscle = "deltscap", .osim_name = "delt_scap_4", .fmax = 117.0, .lceopt = 0.066600000000000006, .lslack = 0.044999999999999998, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.02639999852160008, .tdeact = 0.083499985387502557, .peeslack = 1.0, .mass = 0.0088800000000000007, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap5", .muscle = "deltscap", .osim_name = "delt_scap_5", .fmax = 120.0, .lceopt = 0.065600000000000006, .lslack = 0.035000000000000003, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.0089099999999999995, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap6", .muscle = "deltscap", .osim_name = "delt_scap_6", .fmax = 285.0, .lceopt = 0.076700000000000004, .lslack = 0.067000000000000004, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.024850000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap7", .muscle = "deltscap", .osim_name = "delt_scap_7", .fmax = 149.0, .lceopt = 0.075399999999999995, .lslack = 0.082000000000000003, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.012749999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap8", .muscle = "deltscap", .osim_name = "delt_scap_8", .fmax = 215.0, .lceopt = 0.070999999999999994, .lslack = 0.065000000000000002, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.017299999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap9", .muscle = "deltscap", .osim_name = "delt_scap_9", .fmax = 286.0, .lceopt = 0.073200000000000001, .lslack = 0.070999999999999994, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.023779999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap10", .muscle = "deltscap", .osim_name = "delt_scap10", .fmax = 445.0, .lceopt = 0.074800000000000005, .lslack = 0.064000000000000001, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0067000000603000013, .tdeact = 0.03429999876520004, .peeslack = 1.0, .mass = 0.037900000000000003, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltscap11", .muscle = "deltscap", .osim_name = "delt_scap11", .fmax = 239.0, .lceopt = 0.073700000000000002, .lslack = 0.048000000000000001, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.020119999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltclav1", .muscle = "deltclav", .osim_name = "delt_clav_1", .fmax = 128.0, .lceopt = 0.083599999999999994, .lslack = 0.062, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.01217, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltclav2", .muscle = "deltclav", .osim_name = "delt_clav_2", .fmax = 160.0, .lceopt = 0.094, .lslack = 0.087999999999999995, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.017010000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltclav3", .muscle = "deltclav", .osim_name = "delt_clav_3", .fmax = 105.0, .lceopt = 0.082400000000000001, .lslack = 0.067000000000000004, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.0098300000000000002, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "deltclav4", .muscle = "deltclav", .osim_name = "delt_clav_4", .fmax = 112.0, .lceopt = 0.099099999999999994, .lslack = 0.072999999999999995, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.01259, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "coracobr1", .muscle = "coracobr", .osim_name = "coracobr_1", .fmax = 201.0, .lceopt = 0.066000000000000003, .lslack = 0.091999999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097000003298000105, .tdeact = 0.041800008694401806, .peeslack = 1.0, .mass = 0.01506, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "coracobr2", .muscle = "coracobr", .osim_name = "coracobr_2", .fmax = 148.0, .lceopt = 0.0683, .lslack = 0.104, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.011509999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "coracobr3", .muscle = "coracobr", .osim_name = "coracobr_3", .fmax = 114.0, .lceopt = 0.072700000000000001, .lslack = 0.113, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.009389999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "infra1", .muscle = "infra", .osim_name = "infra_1", .fmax = 272.0, .lceopt = 0.063299999999999995, .lslack = 0.037999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.019609999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "infra2", .muscle = "infra", .osim_name = "infra_2", .fmax = 275.0, .lceopt = 0.071900000000000006, .lslack = 0.107, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.022450000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "infra3", .muscle = "infra", .osim_name = "infra_3", .fmax = 194.0, .lceopt = 0.067699999999999996, .lslack = 0.084000000000000005, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.0, .mass = 0.014880000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "infra4", .muscle = "infra", .osim_name = "infra_4", .fmax = 207.0, .lceopt = 0.0693, .lslack = 0.070999999999999994, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0060999998597000039, .tdeact = 0.032699999738400001, .peeslack = 1.1000000000000001, .mass = 0.016310000000000002, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "infra5", .muscle = "infra", .osim_name = "infra_5", .fmax = 302.0, .lceopt = 0.069800000000000001, .lslack = 0.050000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.2, .mass = 0.024140000000000002, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "infra6", .muscle = "infra", .osim_name = "infra_6", .fmax = 182.0, .lceopt = 0.075300000000000006, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.1000000000000001, .mass = 0.015640000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termin1", .muscle = "termin", .osim_name = "ter_min_1", .fmax = 122.0, .lceopt = 0.050099999999999999, .lslack = 0.049000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.3, .mass = 0.0071400000000000005, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termin2", .muscle = "termin", .osim_name = "ter_min_2", .fmax = 195.0, .lceopt = 0.055, .lslack = 0.050999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.3999999999999999, .mass = 0.01221, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termin3", .muscle = "termin", .osim_name = "ter_min_3", .fmax = 180.0, .lceopt = 0.050599999999999999, .lslack = 0.017999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.3999999999999999, .mass = 0.010410000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termaj1", .muscle = "termaj", .osim_name = "ter_maj_1", .fmax = 165.0, .lceopt = 0.1411, .lslack = 0.0060000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0093000001488000011, .tdeact = 0.04070000757020141, .peeslack = 1.0, .mass = 0.026429999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termaj2", .muscle = "termaj", .osim_name = "ter_maj_2", .fmax = 85.0, .lceopt = 0.1595, .lslack = 0.012, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.01549, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termaj3", .muscle = "termaj", .osim_name = "ter_maj_3", .fmax = 200.0, .lceopt = 0.15260000000000001, .lslack = 0.014999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.034810000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "termaj4", .muscle = "termaj", .osim_name = "ter_maj_4", .fmax = 158.0, .lceopt = 0.10929999999999999, .lslack = 0.034000000000000002, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.019709999999999998, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "supra1", .muscle = "supra", .osim_name = "supra_1", .fmax = 120.0, .lceopt = 0.054100000000000002, .lslack = 0.017000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.1000000000000001, .mass = 0.0073999999999999995, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "supra2", .muscle = "supra", .osim_name = "supra_2", .fmax = 113.0, .lceopt = 0.0591, .lslack = 0.025000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.0075599999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "supra3", .muscle = "supra", .osim_name = "supra_3", .fmax = 258.0, .lceopt = 0.056399999999999999, .lslack = 0.051999999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0080000000000000002, .tdeact = 0.037600006617601163, .peeslack = 1.0, .mass = 0.01651, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "supra4", .muscle = "supra", .osim_name = "supra_4", .fmax = 130.0, .lceopt = 0.055399999999999998, .lslack = 0.031, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.0081899999999999994, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap1", .muscle = "subscap", .osim_name = "subscap_1", .fmax = 44.0, .lceopt = 0.055599999999999997, .lslack = 0.028000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.00281, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap2", .muscle = "subscap", .osim_name = "subscap_2", .fmax = 78.0, .lceopt = 0.064899999999999999, .lslack = 0.043999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.0057499999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap3", .muscle = "subscap", .osim_name = "subscap_3", .fmax = 264.0, .lceopt = 0.067599999999999993, .lslack = 0.058999999999999997, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.020209999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap4", .muscle = "subscap", .osim_name = "subscap_4", .fmax = 274.0, .lceopt = 0.074399999999999994, .lslack = 0.055, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.02376, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap5", .muscle = "subscap", .osim_name = "subscap_5", .fmax = 114.0, .lceopt = 0.079699999999999993, .lslack = 0.066000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.010330000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap6", .muscle = "subscap", .osim_name = "subscap_6", .fmax = 149.0, .lceopt = 0.076200000000000004, .lslack = 0.076999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.012919999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap7", .muscle = "subscap", .osim_name = "subscap_7", .fmax = 162.0, .lceopt = 0.082000000000000003, .lslack = 0.079000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.015129999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap8", .muscle = "subscap", .osim_name = "subscap_8", .fmax = 61.0, .lceopt = 0.076499999999999999, .lslack = 0.040000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.0053200000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap9", .muscle = "subscap", .osim_name = "subscap_9", .fmax = 222.0, .lceopt = 0.072099999999999997, .lslack = 0.058999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.018200000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap10", .muscle = "subscap", .osim_name = "subscap10", .fmax = 47.0, .lceopt = 0.067599999999999993, .lslack = 0.01, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.0036099999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "subscap11", .muscle = "subscap", .osim_name = "subscap11", .fmax = 16.0, .lceopt = 0.064299999999999996, .lslack = 0.01, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.00115, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "bicl", .muscle = "bicl", .osim_name = "bic_l", .fmax = 347.0, .lceopt = 0.12920000000000001, .lslack = 0.23350000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.3, .mass = 0.066199999999999995, .crosses_gh = 1, .dof_mask = 31, .max_activation = 1.0},
    {.name = "bicb1", .muscle = "bicb", .osim_name = "bic_b_1", .fmax = 173.0, .lceopt = 0.11700000000000001, .lslack = 0.1913, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.5, .mass = 0.020789999999999999, .crosses_gh = 1, .dof_mask = 31, .max_activation = 1.0},
    {.name = "bicb2", .muscle = "bicb", .osim_name = "bic_b_2", .fmax = 322.0, .lceopt = 0.1149, .lslack = 0.19270000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.6000000000000001, .mass = 0.03107, .crosses_gh = 1, .dof_mask = 31, .max_activation = 1.0},
    {.name = "triclong1", .muscle = "triclong", .osim_name = "tric_long_1", .fmax = 223.0, .lceopt = 0.1008, .lslack = 0.2041, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.5, .mass = 0.026970000000000001, .crosses_gh = 1, .dof_mask = 15, .max_activation = 1.0},
    {.name = "triclong2", .muscle = "triclong", .osim_name = "tric_long_2", .fmax = 296.0, .lceopt = 0.088099999999999998, .lslack = 0.21929999999999999, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.5, .mass = 0.02955, .crosses_gh = 1, .dof_mask = 15, .max_activation = 1.0},
    {.name = "triclong3", .muscle = "triclong", .osim_name = "tric_long_3", .fmax = 283.0, .lceopt = 0.1183, .lslack = 0.218, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.02964, .crosses_gh = 1, .dof_mask = 15, .max_activation = 1.0},
    {.name = "triclong4", .muscle = "triclong", .osim_name = "tric_long_4", .fmax = 327.0, .lceopt = 0.1226, .lslack = 0.21970000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.032030000000000003, .crosses_gh = 1, .dof_mask = 15, .max_activation = 1.0},
    {.name = "latdorsi1", .muscle = "latdorsi", .osim_name = "lat_dorsi_1", .fmax = 56.0, .lceopt = 0.23430000000000001, .lslack = 0.089999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.01498, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "latdorsi2", .muscle = "latdorsi", .osim_name = "lat_dorsi_2", .fmax = 88.0, .lceopt = 0.28570000000000001, .lslack = 0.083000000000000004, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.028830000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "latdorsi3", .muscle = "latdorsi", .osim_name = "lat_dorsi_3", .fmax = 129.0, .lceopt = 0.29509999999999997, .lslack = 0.105, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.043049999999999998, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "latdorsi4", .muscle = "latdorsi", .osim_name = "lat_dorsi_4", .fmax = 96.0, .lceopt = 0.3206, .lslack = 0.12, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.035150000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "latdorsi5", .muscle = "latdorsi", .osim_name = "lat_dorsi_5", .fmax = 88.0, .lceopt = 0.31290000000000001, .lslack = 0.071999999999999995, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.031570000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "latdorsi6", .muscle = "latdorsi", .osim_name = "lat_dorsi_6", .fmax = 105.0, .lceopt = 0.3402, .lslack = 0.069000000000000006, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.040689999999999997, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajt1", .muscle = "pectmajt", .osim_name = "pect_maj_t_1", .fmax = 125.0, .lceopt = 0.18840000000000001, .lslack = 0.035999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.011799998985200089, .tdeact = 0.046999990600001887, .peeslack = 1.0, .mass = 0.026919999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajt2", .muscle = "pectmajt", .osim_name = "pect_maj_t_2", .fmax = 118.0, .lceopt = 0.183, .lslack = 0.042999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.024479999999999998, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajt3", .muscle = "pectmajt", .osim_name = "pect_maj_t_3", .fmax = 165.0, .lceopt = 0.18529999999999999, .lslack = 0.052999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0097999996472000108, .tdeact = 0.042099998442300057, .peeslack = 1.0, .mass = 0.034750000000000003, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajt4", .muscle = "pectmajt", .osim_name = "pect_maj_t_4", .fmax = 157.0, .lceopt = 0.18329999999999999, .lslack = 0.028000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.033009999999999998, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajt5", .muscle = "pectmajt", .osim_name = "pect_maj_t_5", .fmax = 133.0, .lceopt = 0.14999999999999999, .lslack = 0.025999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.0071000000213000004, .tdeact = 0.035300002365100155, .peeslack = 1.0, .mass = 0.02273, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajt6", .muscle = "pectmajt", .osim_name = "pect_maj_t_6", .fmax = 198.0, .lceopt = 0.1449, .lslack = 0.035999999999999997, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.03243, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajc1", .muscle = "pectmajc", .osim_name = "pect_maj_c_1", .fmax = 179.0, .lceopt = 0.1363, .lslack = 0.017000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.027689999999999999, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "pectmajc2", .muscle = "pectmajc", .osim_name = "pect_maj_c_2", .fmax = 113.0, .lceopt = 0.1091, .lslack = 0.014, .pennopt = 0.0, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.0, .mass = 0.013990000000000001, .crosses_gh = 1, .dof_mask = 7, .max_activation = 1.0},
    {.name = "tricmed1", .muscle = "tricmed", .osim_name = "tric_med_1", .fmax = 263.0, .lceopt = 0.080699999999999994, .lslack = 0.087499999999999994, .pennopt = 0.29670597283900002, .vmax = 10.0, .tact = 0.015900000445200013, .tdeact = 0.057199991763201181, .peeslack = 1.3, .mass = 0.0184, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "tricmed2", .muscle = "tricmed", .osim_name = "tric_med_2", .fmax = 256.0, .lceopt = 0.077299999999999994, .lslack = 0.11219999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.017649999999999999, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "tricmed3", .muscle = "tricmed", .osim_name = "tric_med_3", .fmax = 240.0, .lceopt = 0.060199999999999997, .lslack = 0.010699999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.011950000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "tricmed4", .muscle = "tricmed", .osim_name = "tric_med_4", .fmax = 211.0, .lceopt = 0.0746, .lslack = 0.040399999999999998, .pennopt = 0.13962634016, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.013950000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "tricmed5", .muscle = "tricmed", .osim_name = "tric_med_5", .fmax = 107.0, .lceopt = 0.080699999999999994, .lslack = 0.073800000000000004, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0077000000000000002, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis1", .muscle = "brachialis", .osim_name = "brachialis_1", .fmax = 314.0, .lceopt = 0.087599999999999997, .lslack = 0.080699999999999994, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.029100000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis2", .muscle = "brachialis", .osim_name = "brachialis_2", .fmax = 158.0, .lceopt = 0.095299999999999996, .lslack = 0.059200000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.015900000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis3", .muscle = "brachialis", .osim_name = "brachialis_3", .fmax = 157.0, .lceopt = 0.086999999999999994, .lslack = 0.039399999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.1000000000000001, .mass = 0.01465, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis4", .muscle = "brachialis", .osim_name = "brachialis_4", .fmax = 87.0, .lceopt = 0.075800000000000006, .lslack = 0.031699999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3999999999999999, .mass = 0.007000000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis5", .muscle = "brachialis", .osim_name = "brachialis_5", .fmax = 101.0, .lceopt = 0.061899999999999997, .lslack = 0.020899999999999998, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0066, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis6", .muscle = "brachialis", .osim_name = "brachialis_6", .fmax = 104.0, .lceopt = 0.047199999999999999, .lslack = 0.035000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0041000000000000003, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachialis7", .muscle = "brachialis", .osim_name = "brachialis_7", .fmax = 118.0, .lceopt = 0.062100000000000002, .lslack = 0.0076, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0065000000000000006, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "brachiorad1", .muscle = "brachiorad", .osim_name = "brachiorad_1", .fmax = 30.0, .lceopt = 0.1613, .lslack = 0.1197, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0047000000000000002, .crosses_gh = 0, .dof_mask = 24, .max_activation = 1.0},
    {.name = "brachiorad2", .muscle = "brachiorad", .osim_name = "brachiorad_2", .fmax = 82.0, .lceopt = 0.1613, .lslack = 0.1197, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.014, .crosses_gh = 0, .dof_mask = 24, .max_activation = 1.0},
    {.name = "brachiorad3", .muscle = "brachiorad", .osim_name = "brachiorad_3", .fmax = 52.0, .lceopt = 0.1066, .lslack = 0.1542, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0059700000000000005, .crosses_gh = 0, .dof_mask = 24, .max_activation = 1.0},
    {.name = "pronteres1", .muscle = "pronteres", .osim_name = "pron_teres_1", .fmax = 510.0, .lceopt = 0.060999999999999999, .lslack = 0.085099999999999995, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0275, .crosses_gh = 0, .dof_mask = 24, .max_activation = 1.0},
    {.name = "pronteres2", .muscle = "pronteres", .osim_name = "pron_teres_2", .fmax = 141.0, .lceopt = 0.039100000000000003, .lslack = 0.048399999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0043299999999999996, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "supinator1", .muscle = "supinator", .osim_name = "supinator_1", .fmax = 47.0, .lceopt = 0.026700000000000002, .lslack = 0.025399999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00084000000000000014, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "supinator2", .muscle = "supinator", .osim_name = "supinator_2", .fmax = 232.0, .lceopt = 0.025999999999999999, .lslack = 0.023099999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.00364, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "supinator3", .muscle = "supinator", .osim_name = "supinator_3", .fmax = 126.0, .lceopt = 0.0252, .lslack = 0.014999999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0033599999999999997, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "supinator4", .muscle = "supinator", .osim_name = "supinator_4", .fmax = 148.0, .lceopt = 0.0263, .lslack = 0.014500000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.00296, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "supinator5", .muscle = "supinator", .osim_name = "supinator_5", .fmax = 285.0, .lceopt = 0.027400000000000001, .lslack = 0.013899999999999999, .pennopt = 0.03490658504, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.3, .mass = 0.0067599999999999995, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "pronquad1", .muscle = "pronquad", .osim_name = "pron_quad_1", .fmax = 73.0, .lceopt = 0.037699999999999997, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.1000000000000001, .mass = 0.0016299999999999999, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "pronquad2", .muscle = "pronquad", .osim_name = "pron_quad_2", .fmax = 178.0, .lceopt = 0.038600000000000002, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00347, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "pronquad3", .muscle = "pronquad", .osim_name = "pron_quad_3", .fmax = 219.0, .lceopt = 0.035200000000000002, .lslack = 0.0050000000000000001, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0049299999999999995, .crosses_gh = 0, .dof_mask = 16, .max_activation = 1.0},
    {.name = "triclat1", .muscle = "triclat", .osim_name = "tric_lat_1", .fmax = 153.0, .lceopt = 0.075800000000000006, .lslack = 0.17069999999999999, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.012500000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "triclat2", .muscle = "triclat", .osim_name = "tric_lat_2", .fmax = 410.0, .lceopt = 0.076600000000000001, .lslack = 0.17699999999999999, .pennopt = 0.087266462599999997, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0332, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "triclat3", .muscle = "triclat", .osim_name = "tric_lat_3", .fmax = 219.0, .lceopt = 0.065600000000000006, .lslack = 0.19109999999999999, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.0152, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "triclat4", .muscle = "triclat", .osim_name = "tric_lat_4", .fmax = 275.0, .lceopt = 0.063799999999999996, .lslack = 0.157, .pennopt = 0.17453292519899999, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.2, .mass = 0.016199999999999999, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "triclat5", .muscle = "triclat", .osim_name = "tric_lat_5", .fmax = 87.0, .lceopt = 0.063799999999999996, .lslack = 0.157, .pennopt = 0.29670597283900002, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0058500000000000002, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "anconeus1", .muscle = "anconeus", .osim_name = "anconeus_1", .fmax = 31.0, .lceopt = 0.0252, .lslack = 0.0064000000000000003, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00083000000000000001, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "anconeus2", .muscle = "anconeus", .osim_name = "anconeus_2", .fmax = 70.0, .lceopt = 0.020199999999999999, .lslack = 0.0080000000000000002, .pennopt = 0.26179938779900003, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0015, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "anconeus3", .muscle = "anconeus", .osim_name = "anconeus_3", .fmax = 25.0, .lceopt = 0.022800000000000001, .lslack = 0.0043, .pennopt = 0.0, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.00060000000000000006, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "anconeus4", .muscle = "anconeus", .osim_name = "anconeus_4", .fmax = 118.0, .lceopt = 0.027, .lslack = 0.029999999999999999, .pennopt = 0.31415926535900002, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0021999999999999997, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
    {.name = "anconeus5", .muscle = "anconeus", .osim_name = "anconeus_5", .fmax = 118.0, .lceopt = 0.026599999999999999, .lslack = 0.02, .pennopt = 0.401425727959, .vmax = 10.0, .tact = 0.012000000480000019, .tdeact = 0.047600007616001215, .peeslack = 1.0, .mass = 0.0033300000000000005, .crosses_gh = 0, .dof_mask = 8, .max_activation = 1.0},
};

const int kMuscle0[11] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
const int kMuscle1[4] = {11, 12, 13, 14};
const int kMuscle2[3] = {15, 16, 17};
const int kMuscle3[6] = {18, 19, 20, 21, 22, 23};
const int kMuscle4[3] = {24, 25, 26};
const int kMuscle5[4] = {27, 28, 29, 30};
const int kMuscle6[4] = {31, 32, 33, 34};
const int kMuscle7[11] = {35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45};
const int kMuscle8[1] = {46};
const int kMuscle9[2] = {47, 48};
const int kMuscle10[4] = {49, 50, 51, 52};
const int kMuscle11[6] = {53, 54, 55, 56, 57, 58};
const int kMuscle12[6] = {59, 60, 61, 62, 63, 64};
const int kMuscle13[2] = {65, 66};
const int kMuscle14[5] = {67, 68, 69, 70, 71};
const int kMuscle15[7] = {72, 73, 74, 75, 76, 77, 78};
const int kMuscle16[3] = {79, 80, 81};
const int kMuscle17[2] = {82, 83};
const int kMuscle18[5] = {84, 85, 86, 87, 88};
const int kMuscle19[3] = {89, 90, 91};
const int kMuscle20[5] = {92, 93, 94, 95, 96};
const int kMuscle21[5] = {97, 98, 99, 100, 101};

const GroupDef kMuscles[22] = {
    {.name = "deltscap", .num_elements = 11, .elements = kMuscle0},
    {.name = "deltclav", .num_elements = 4, .elements = kMuscle1},
    {.name = "coracobr", .num_elements = 3, .elements = kMuscle2},
    {.name = "infra", .num_elements = 6, .elements = kMuscle3},
    {.name = "termin", .num_elements = 3, .elements = kMuscle4},
    {.name = "termaj", .num_elements = 4, .elements = kMuscle5},
    {.name = "supra", .num_elements = 4, .elements = kMuscle6},
    {.name = "subscap", .num_elements = 11, .elements = kMuscle7},
    {.name = "bicl", .num_elements = 1, .elements = kMuscle8},
    {.name = "bicb", .num_elements = 2, .elements = kMuscle9},
    {.name = "triclong", .num_elements = 4, .elements = kMuscle10},
    {.name = "latdorsi", .num_elements = 6, .elements = kMuscle11},
    {.name = "pectmajt", .num_elements = 6, .elements = kMuscle12},
    {.name = "pectmajc", .num_elements = 2, .elements = kMuscle13},
    {.name = "tricmed", .num_elements = 5, .elements = kMuscle14},
    {.name = "brachialis", .num_elements = 7, .elements = kMuscle15},
    {.name = "brachiorad", .num_elements = 3, .elements = kMuscle16},
    {.name = "pronteres", .num_elements = 2, .elements = kMuscle17},
    {.name = "supinator", .num_elements = 5, .elements = kMuscle18},
    {.name = "pronquad", .num_elements = 3, .elements = kMuscle19},
    {.name = "triclat", .num_elements = 5, .elements = kMuscle20},
    {.name = "anconeus", .num_elements = 5, .elements = kMuscle21},
};

const int kGroup0[24] = {18, 19, 20, 21, 22, 23, 24, 25, 26, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45};
const int kGroup1[15] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
const int kGroup2[13] = {46, 47, 48, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81};
const int kGroup3[19] = {49, 50, 51, 52, 67, 68, 69, 70, 71, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101};
const int kGroup4[5] = {82, 83, 89, 90, 91};
const int kGroup5[5] = {84, 85, 86, 87, 88};
const int kGroup6[3] = {46, 47, 48};
const int kGroup7[14] = {49, 50, 51, 52, 67, 68, 69, 70, 71, 92, 93, 94, 95, 96};
const int kGroup8[8] = {59, 60, 61, 62, 63, 64, 65, 66};

const GroupDef kGroups[9] = {
    {.name = "rotator_cuff", .num_elements = 24, .elements = kGroup0},
    {.name = "deltoid", .num_elements = 15, .elements = kGroup1},
    {.name = "elbow_flexors", .num_elements = 13, .elements = kGroup2},
    {.name = "elbow_extensors", .num_elements = 19, .elements = kGroup3},
    {.name = "pronators", .num_elements = 5, .elements = kGroup4},
    {.name = "supinators", .num_elements = 5, .elements = kGroup5},
    {.name = "biceps", .num_elements = 3, .elements = kGroup6},
    {.name = "triceps", .num_elements = 14, .elements = kGroup7},
    {.name = "pectoralis_major", .num_elements = 8, .elements = kGroup8},
};

const char* const kBodyNames[4] = {"humerus", "ulna", "radius", "hand"};

const ModelDef kModel = {
    .name = "das2",
    .source_hash = "effb6ef66ec79560b06b1541ad3764787289ecb15b03c0a146d0090edd57a0b0",
    .num_dofs = 5,
    .num_elements = 102,
    .dofs = kDofs,
    .elements = kElements,
    .num_muscles = 22,
    .muscles = kMuscles,
    .num_groups = 9,
    .groups = kGroups,
    .base_body = "scapula",
    .gravity_base = {1.9151805406858844, -9.4078806812419753, -1.9985616844601333},
    .base_rotation_in_thorax = {0.93779623202356432, 0.12184584092939055, 0.3251027810564136, -0.19529406481172312, 0.95933684604242797, 0.20379657522804764, -0.28705131153109059, -0.25461030394227269, 0.9234582490154627},
    .base_origin_in_thorax = {0.18412016703277295, 0.0058219860086753932, 0.10332838735285975},
    .num_bodies = 4,
    .body_names = kBodyNames,
    .scapula_body = -1,
    .humerus_body = 0,
    .girdle = nullptr,
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

}  // namespace armrt::generated::das2
