// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das3.json --out cpp/generated`
// from the model file das3.json (sha256 9289e81ac11b44228bbcac078e6e0a2af00fdbe2eabf7ee115c9eac3ffce5409).
// Change the model file or the generator and regenerate instead.

#include <cmath>
#include <cstring>

#include "das3.h"

namespace armrt::generated::das3 {

// muscle_paths writes its moment arms in rows of 160 (model_def.h): the engine must agree.
static_assert(kMaxElements == 160, "rebuild this model: the engine's kMaxElements changed");

// Four doubles, one AVX2 register: one group's moment arms and a length lane.
using v4d = double __attribute__((vector_size(32)));

void muscle_lengths(const double* q, double* L) {
  double moment_arm[11 * kMaxElements];
  muscle_paths(q, L, moment_arm);
}

void muscle_paths(const double* q, double* L, double* moment_arm) {
  // DOF groups (_grouped_paths) 0: DOFs 0..2, 1: DOFs 3..5, 2: DOFs 6..8, 3: DOFs 9..10.
  for (int j = 0; j < 11; ++j)  // the DOFs an element does not cross
    std::memset(moment_arm + j * kMaxElements, 0, 138 * sizeof(double));
  const double q0 = q[0];
  const double q1 = q[1];
  const double q2 = q[2];
  const double q3 = q[3];
  const double q4 = q[4];
  const double q5 = q[5];
  const double q6 = q[6];
  const double q7 = q[7];
  const double q8 = q[8];
  const double q9 = q[9];
  const double q10 = q[10];
  const v4d e_len = {0.0, 0.0, 0.0, 1.0};
  const v4d e0 = {1.0, 0.0, 0.0, 0.0};
  const v4d e1 = {0.0, 1.0, 0.0, 0.0};
  const v4d e2 = {0.0, 0.0, 1.0, 0.0};
  const v4d e3 = {1.0, 0.0, 0.0, 0.0};
  const v4d e4 = {0.0, 1.0, 0.0, 0.0};
  const v4d e5 = {0.0, 0.0, 1.0, 0.0};
  const v4d e6 = {1.0, 0.0, 0.0, 0.0};
  const v4d e7 = {0.0, 1.0, 0.0, 0.0};
  const v4d e8 = {0.0, 0.0, 1.0, 0.0};
  const v4d e9 = {1.0, 0.0, 0.0, 0.0};
  const v4d e10 = {0.0, 1.0, 0.0, 0.0};
  const double p0 = q10;
  const double p1 = q9;
  const double p2 = q8;
  const double p3 = q7;
  const double p4 = q6;
  const double p5 = q5;
  const double p6 = q4;
  const double p7 = q3;
  const double p8 = q2;
  const double p9 = q1;
  const double p10 = q0;
  const double p11 = q10*p0;
  const double p12 = q10*p1;
  const double p13 = q9*p1;
  const double p14 = q9*p2;
  const double p15 = q8*p2;
  const double p16 = q8*p3;
  const double p17 = q7*p3;
  const double p18 = q8*p4;
  const double p19 = q7*p4;
  const double p20 = q6*p4;
  const double p21 = q8*p5;
  const double p22 = q7*p5;
  const double p23 = q6*p5;
  const double p24 = q5*p5;
  const double p25 = q8*p6;
  const double p26 = q7*p6;
  const double p27 = q6*p6;
  const double p28 = q5*p6;
  const double p29 = q4*p6;
  const double p30 = q8*p7;
  const double p31 = q7*p7;
  const double p32 = q6*p7;
  const double p33 = q5*p7;
  const double p34 = q4*p7;
  const double p35 = q3*p7;
  const double p36 = q8*p8;
  const double p37 = q7*p8;
  const double p38 = q6*p8;
  const double p39 = q5*p8;
  const double p40 = q4*p8;
  const double p41 = q3*p8;
  const double p42 = q2*p8;
  const double p43 = q8*p9;
  const double p44 = q7*p9;
  const double p45 = q6*p9;
  const double p46 = q5*p9;
  const double p47 = q4*p9;
  const double p48 = q3*p9;
  const double p49 = q2*p9;
  const double p50 = q1*p9;
  const double p52 = q7*p10;
  const double p53 = q6*p10;
  const double p54 = q5*p10;
  const double p55 = q4*p10;
  const double p56 = q3*p10;
  const double p57 = q2*p10;
  const double p58 = q1*p10;
  const double p59 = q0*p10;
  const double p60 = q10*p11;
  const double p61 = q10*p12;
  const double p62 = q10*p13;
  const double p63 = q9*p13;
  const double p64 = q9*p14;
  const double p66 = q8*p15;
  const double p67 = q8*p16;
  const double p68 = q8*p17;
  const double p69 = q7*p17;
  const double p70 = q8*p18;
  const double p71 = q8*p19;
  const double p72 = q7*p19;
  const double p73 = q8*p20;
  const double p74 = q7*p20;
  const double p75 = q6*p20;
  const double p213 = q1*p59;
  const double p214 = q0*p59;
  const double p215 = q10*p60;
  const double p216 = q10*p61;
  const double p217 = q10*p62;
  const double p218 = q10*p63;
  const double p219 = q9*p63;
  const double p221 = q8*p66;
  const double p223 = q8*p68;
  const double p224 = q8*p69;
  const double p225 = q7*p69;
  const double p226 = q8*p70;
  const double p227 = q8*p71;
  const double p228 = q8*p72;
  const double p229 = q7*p72;
  const double p230 = q8*p73;
  const double p231 = q8*p74;
  const double p232 = q7*p74;
  const double p233 = q8*p75;
  const double p234 = q7*p75;
  const double p235 = q6*p75;
  const double p237 = q1*p214;
  const double p238 = q0*p214;
  const double p239 = q10*p215;
  const double p240 = q10*p216;
  const double p241 = q10*p217;
  const double p243 = q9*p219;
  const double p244 = q8*p221;
  const double p246 = q8*p224;
  const double p247 = q8*p225;
  const double p248 = q7*p225;
  const double p249 = q8*p226;
  const double p250 = q8*p227;
  const double p251 = q8*p228;
  const double p252 = q8*p229;
  const double p253 = q7*p229;
  const double p254 = q8*p230;
  const double p255 = q8*p231;
  const double p256 = q8*p232;
  const double p257 = q7*p232;
  const double p258 = q8*p233;
  const double p259 = q8*p234;
  const double p260 = q7*p234;
  const double p261 = q8*p235;
  const double p262 = q7*p235;
  const double p263 = q6*p235;
  const double p265 = q1*p238;
  const double p266 = q0*p238;
  const double p267 = q10*p239;
  const double p269 = q10*p241;
  const double p270 = q10*p243;
  const double p271 = q9*p243;
  const double p301 = q10*p267;
  const double p305 = q9*p271;
  const double p306 = q10*p301;
  const double p307 = q9*p305;
  const v4d g0_3 = p0*e_len - e10;
  const v4d g1_3 = p1*e_len - e9;
  const v4d g2_2 = p2*e_len - e8;
  const v4d g3_2 = p3*e_len - e7;
  const v4d g4_2 = p4*e_len - e6;
  const v4d g5_1 = p5*e_len - e5;
  const v4d g6_1 = p6*e_len - e4;
  const v4d g7_1 = p7*e_len - e3;
  const v4d g8_0 = p8*e_len - e2;
  const v4d g9_0 = p9*e_len - e1;
  const v4d g10_0 = p10*e_len - e0;
  const v4d g11_3 = q10*g0_3 - p0*e10;
  const v4d g12_3 = q10*g1_3 - p1*e10;
  const v4d g13_3 = q9*g1_3 - p1*e9;
  const v4d g14_2 = q9*g2_2;
  const v4d g14_3 = -p2*e9;
  const v4d g15_2 = q8*g2_2 - p2*e8;
  const v4d g16_2 = q8*g3_2 - p3*e8;
  const v4d g17_2 = q7*g3_2 - p3*e7;
  const v4d g18_2 = q8*g4_2 - p4*e8;
  const v4d g19_2 = q7*g4_2 - p4*e7;
  const v4d g20_2 = q6*g4_2 - p4*e6;
  const v4d g21_1 = q8*g5_1;
  const v4d g21_2 = -p5*e8;
  const v4d g22_1 = q7*g5_1;
  const v4d g22_2 = -p5*e7;
  const v4d g23_1 = q6*g5_1;
  const v4d g23_2 = -p5*e6;
  const v4d g24_1 = q5*g5_1 - p5*e5;
  const v4d g25_1 = q8*g6_1;
  const v4d g25_2 = -p6*e8;
  const v4d g26_1 = q7*g6_1;
  const v4d g26_2 = -p6*e7;
  const v4d g27_1 = q6*g6_1;
  const v4d g27_2 = -p6*e6;
  const v4d g28_1 = q5*g6_1 - p6*e5;
  const v4d g29_1 = q4*g6_1 - p6*e4;
  const v4d g30_1 = q8*g7_1;
  const v4d g30_2 = -p7*e8;
  const v4d g31_1 = q7*g7_1;
  const v4d g31_2 = -p7*e7;
  const v4d g32_1 = q6*g7_1;
  const v4d g32_2 = -p7*e6;
  const v4d g33_1 = q5*g7_1 - p7*e5;
  const v4d g34_1 = q4*g7_1 - p7*e4;
  const v4d g35_1 = q3*g7_1 - p7*e3;
  const v4d g36_0 = q8*g8_0;
  const v4d g36_2 = -p8*e8;
  const v4d g37_0 = q7*g8_0;
  const v4d g37_2 = -p8*e7;
  const v4d g38_0 = q6*g8_0;
  const v4d g38_2 = -p8*e6;
  const v4d g39_0 = q5*g8_0;
  const v4d g39_1 = -p8*e5;
  const v4d g40_0 = q4*g8_0;
  const v4d g40_1 = -p8*e4;
  const v4d g41_0 = q3*g8_0;
  const v4d g41_1 = -p8*e3;
  const v4d g42_0 = q2*g8_0 - p8*e2;
  const v4d g43_0 = q8*g9_0;
  const v4d g43_2 = -p9*e8;
  const v4d g44_0 = q7*g9_0;
  const v4d g44_2 = -p9*e7;
  const v4d g45_0 = q6*g9_0;
  const v4d g45_2 = -p9*e6;
  const v4d g46_0 = q5*g9_0;
  const v4d g46_1 = -p9*e5;
  const v4d g47_0 = q4*g9_0;
  const v4d g47_1 = -p9*e4;
  const v4d g48_0 = q3*g9_0;
  const v4d g48_1 = -p9*e3;
  const v4d g49_0 = q2*g9_0 - p9*e2;
  const v4d g50_0 = q1*g9_0 - p9*e1;
  const v4d g51_0 = q8*g10_0;
  const v4d g51_2 = -p10*e8;
  const v4d g52_0 = q7*g10_0;
  const v4d g52_2 = -p10*e7;
  const v4d g53_0 = q6*g10_0;
  const v4d g53_2 = -p10*e6;
  const v4d g54_0 = q5*g10_0;
  const v4d g54_1 = -p10*e5;
  const v4d g55_0 = q4*g10_0;
  const v4d g55_1 = -p10*e4;
  const v4d g56_0 = q3*g10_0;
  const v4d g56_1 = -p10*e3;
  const v4d g57_0 = q2*g10_0 - p10*e2;
  const v4d g58_0 = q1*g10_0 - p10*e1;
  const v4d g59_0 = q0*g10_0 - p10*e0;
  const v4d g60_3 = q10*g11_3 - p11*e10;
  const v4d g61_3 = q10*g12_3 - p12*e10;
  const v4d g62_3 = q10*g13_3 - p13*e10;
  const v4d g63_3 = q9*g13_3 - p13*e9;
  const v4d g64_2 = q9*g14_2;
  const v4d g64_3 = q9*g14_3 - p14*e9;
  const v4d g65_2 = q9*g15_2;
  const v4d g65_3 = -p15*e9;
  const v4d g66_2 = q8*g15_2 - p15*e8;
  const v4d g67_2 = q8*g16_2 - p16*e8;
  const v4d g68_2 = q8*g17_2 - p17*e8;
  const v4d g69_2 = q7*g17_2 - p17*e7;
  const v4d g70_2 = q8*g18_2 - p18*e8;
  const v4d g71_2 = q8*g19_2 - p19*e8;
  const v4d g72_2 = q7*g19_2 - p19*e7;
  const v4d g73_2 = q8*g20_2 - p20*e8;
  const v4d g74_2 = q7*g20_2 - p20*e7;
  const v4d g75_2 = q6*g20_2 - p20*e6;
  const v4d g76_1 = q8*g21_1;
  const v4d g76_2 = q8*g21_2 - p21*e8;
  const v4d g77_1 = q8*g22_1;
  const v4d g77_2 = q8*g22_2 - p22*e8;
  const v4d g78_1 = q7*g22_1;
  const v4d g78_2 = q7*g22_2 - p22*e7;
  const v4d g79_1 = q8*g23_1;
  const v4d g79_2 = q8*g23_2 - p23*e8;
  const v4d g80_1 = q7*g23_1;
  const v4d g80_2 = q7*g23_2 - p23*e7;
  const v4d g81_1 = q6*g23_1;
  const v4d g81_2 = q6*g23_2 - p23*e6;
  const v4d g82_1 = q7*g24_1;
  const v4d g82_2 = -p24*e7;
  const v4d g83_1 = q6*g24_1;
  const v4d g83_2 = -p24*e6;
  const v4d g84_1 = q5*g24_1 - p24*e5;
  const v4d g85_1 = q8*g25_1;
  const v4d g85_2 = q8*g25_2 - p25*e8;
  const v4d g86_1 = q8*g26_1;
  const v4d g86_2 = q8*g26_2 - p26*e8;
  const v4d g87_1 = q7*g26_1;
  const v4d g87_2 = q7*g26_2 - p26*e7;
  const v4d g88_1 = q8*g27_1;
  const v4d g88_2 = q8*g27_2 - p27*e8;
  const v4d g89_1 = q7*g27_1;
  const v4d g89_2 = q7*g27_2 - p27*e7;
  const v4d g90_1 = q6*g27_1;
  const v4d g90_2 = q6*g27_2 - p27*e6;
  const v4d g91_1 = q8*g28_1;
  const v4d g91_2 = -p28*e8;
  const v4d g92_1 = q7*g28_1;
  const v4d g92_2 = -p28*e7;
  const v4d g93_1 = q6*g28_1;
  const v4d g93_2 = -p28*e6;
  const v4d g94_1 = q5*g28_1 - p28*e5;
  const v4d g95_1 = q8*g29_1;
  const v4d g95_2 = -p29*e8;
  const v4d g96_1 = q7*g29_1;
  const v4d g96_2 = -p29*e7;
  const v4d g97_1 = q6*g29_1;
  const v4d g97_2 = -p29*e6;
  const v4d g98_1 = q5*g29_1 - p29*e5;
  const v4d g99_1 = q4*g29_1 - p29*e4;
  const v4d g100_1 = q8*g30_1;
  const v4d g100_2 = q8*g30_2 - p30*e8;
  const v4d g101_1 = q8*g31_1;
  const v4d g101_2 = q8*g31_2 - p31*e8;
  const v4d g102_1 = q7*g31_1;
  const v4d g102_2 = q7*g31_2 - p31*e7;
  const v4d g103_1 = q8*g32_1;
  const v4d g103_2 = q8*g32_2 - p32*e8;
  const v4d g104_1 = q7*g32_1;
  const v4d g104_2 = q7*g32_2 - p32*e7;
  const v4d g105_1 = q6*g32_1;
  const v4d g105_2 = q6*g32_2 - p32*e6;
  const v4d g106_1 = q8*g33_1;
  const v4d g106_2 = -p33*e8;
  const v4d g107_1 = q7*g33_1;
  const v4d g107_2 = -p33*e7;
  const v4d g108_1 = q6*g33_1;
  const v4d g108_2 = -p33*e6;
  const v4d g109_1 = q5*g33_1 - p33*e5;
  const v4d g110_1 = q8*g34_1;
  const v4d g110_2 = -p34*e8;
  const v4d g111_1 = q7*g34_1;
  const v4d g111_2 = -p34*e7;
  const v4d g112_1 = q6*g34_1;
  const v4d g112_2 = -p34*e6;
  const v4d g113_1 = q5*g34_1 - p34*e5;
  const v4d g114_1 = q4*g34_1 - p34*e4;
  const v4d g115_1 = q8*g35_1;
  const v4d g115_2 = -p35*e8;
  const v4d g116_1 = q7*g35_1;
  const v4d g116_2 = -p35*e7;
  const v4d g117_1 = q6*g35_1;
  const v4d g117_2 = -p35*e6;
  const v4d g118_1 = q5*g35_1 - p35*e5;
  const v4d g119_1 = q4*g35_1 - p35*e4;
  const v4d g120_1 = q3*g35_1 - p35*e3;
  const v4d g121_0 = q8*g36_0;
  const v4d g121_2 = q8*g36_2 - p36*e8;
  const v4d g122_0 = q8*g37_0;
  const v4d g122_2 = q8*g37_2 - p37*e8;
  const v4d g123_0 = q7*g37_0;
  const v4d g123_2 = q7*g37_2 - p37*e7;
  const v4d g124_0 = q8*g38_0;
  const v4d g124_2 = q8*g38_2 - p38*e8;
  const v4d g125_0 = q7*g38_0;
  const v4d g125_2 = q7*g38_2 - p38*e7;
  const v4d g126_0 = q6*g38_0;
  const v4d g126_2 = q6*g38_2 - p38*e6;
  const v4d g127_0 = q8*g39_0;
  const v4d g127_1 = q8*g39_1;
  const v4d g127_2 = -p39*e8;
  const v4d g128_0 = q7*g39_0;
  const v4d g128_1 = q7*g39_1;
  const v4d g128_2 = -p39*e7;
  const v4d g129_0 = q6*g39_0;
  const v4d g129_1 = q6*g39_1;
  const v4d g129_2 = -p39*e6;
  const v4d g130_0 = q5*g39_0;
  const v4d g130_1 = q5*g39_1 - p39*e5;
  const v4d g131_0 = q8*g40_0;
  const v4d g131_1 = q8*g40_1;
  const v4d g131_2 = -p40*e8;
  const v4d g132_0 = q7*g40_0;
  const v4d g132_1 = q7*g40_1;
  const v4d g132_2 = -p40*e7;
  const v4d g133_0 = q6*g40_0;
  const v4d g133_1 = q6*g40_1;
  const v4d g133_2 = -p40*e6;
  const v4d g134_0 = q5*g40_0;
  const v4d g134_1 = q5*g40_1 - p40*e5;
  const v4d g135_0 = q4*g40_0;
  const v4d g135_1 = q4*g40_1 - p40*e4;
  const v4d g136_0 = q7*g41_0;
  const v4d g136_1 = q7*g41_1;
  const v4d g136_2 = -p41*e7;
  const v4d g137_0 = q6*g41_0;
  const v4d g137_1 = q6*g41_1;
  const v4d g137_2 = -p41*e6;
  const v4d g138_0 = q5*g41_0;
  const v4d g138_1 = q5*g41_1 - p41*e5;
  const v4d g139_0 = q4*g41_0;
  const v4d g139_1 = q4*g41_1 - p41*e4;
  const v4d g140_0 = q3*g41_0;
  const v4d g140_1 = q3*g41_1 - p41*e3;
  const v4d g141_0 = q8*g42_0;
  const v4d g141_2 = -p42*e8;
  const v4d g142_0 = q7*g42_0;
  const v4d g142_2 = -p42*e7;
  const v4d g143_0 = q6*g42_0;
  const v4d g143_2 = -p42*e6;
  const v4d g144_0 = q5*g42_0;
  const v4d g144_1 = -p42*e5;
  const v4d g145_0 = q4*g42_0;
  const v4d g145_1 = -p42*e4;
  const v4d g146_0 = q3*g42_0;
  const v4d g146_1 = -p42*e3;
  const v4d g147_0 = q2*g42_0 - p42*e2;
  const v4d g148_0 = q8*g43_0;
  const v4d g148_2 = q8*g43_2 - p43*e8;
  const v4d g149_0 = q8*g44_0;
  const v4d g149_2 = q8*g44_2 - p44*e8;
  const v4d g150_0 = q7*g44_0;
  const v4d g150_2 = q7*g44_2 - p44*e7;
  const v4d g151_0 = q7*g45_0;
  const v4d g151_2 = q7*g45_2 - p45*e7;
  const v4d g152_0 = q6*g45_0;
  const v4d g152_2 = q6*g45_2 - p45*e6;
  const v4d g153_0 = q5*g46_0;
  const v4d g153_1 = q5*g46_1 - p46*e5;
  const v4d g154_0 = q7*g47_0;
  const v4d g154_1 = q7*g47_1;
  const v4d g154_2 = -p47*e7;
  const v4d g155_0 = q6*g47_0;
  const v4d g155_1 = q6*g47_1;
  const v4d g155_2 = -p47*e6;
  const v4d g156_0 = q5*g47_0;
  const v4d g156_1 = q5*g47_1 - p47*e5;
  const v4d g157_0 = q4*g47_0;
  const v4d g157_1 = q4*g47_1 - p47*e4;
  const v4d g158_0 = q8*g48_0;
  const v4d g158_1 = q8*g48_1;
  const v4d g158_2 = -p48*e8;
  const v4d g159_0 = q7*g48_0;
  const v4d g159_1 = q7*g48_1;
  const v4d g159_2 = -p48*e7;
  const v4d g160_0 = q6*g48_0;
  const v4d g160_1 = q6*g48_1;
  const v4d g160_2 = -p48*e6;
  const v4d g161_0 = q5*g48_0;
  const v4d g161_1 = q5*g48_1 - p48*e5;
  const v4d g162_0 = q4*g48_0;
  const v4d g162_1 = q4*g48_1 - p48*e4;
  const v4d g163_0 = q3*g48_0;
  const v4d g163_1 = q3*g48_1 - p48*e3;
  const v4d g164_0 = q8*g49_0;
  const v4d g164_2 = -p49*e8;
  const v4d g165_0 = q7*g49_0;
  const v4d g165_2 = -p49*e7;
  const v4d g166_0 = q6*g49_0;
  const v4d g166_2 = -p49*e6;
  const v4d g167_0 = q5*g49_0;
  const v4d g167_1 = -p49*e5;
  const v4d g168_0 = q4*g49_0;
  const v4d g168_1 = -p49*e4;
  const v4d g169_0 = q3*g49_0;
  const v4d g169_1 = -p49*e3;
  const v4d g170_0 = q2*g49_0 - p49*e2;
  const v4d g171_0 = q7*g50_0;
  const v4d g171_2 = -p50*e7;
  const v4d g172_0 = q5*g50_0;
  const v4d g172_1 = -p50*e5;
  const v4d g173_0 = q4*g50_0;
  const v4d g173_1 = -p50*e4;
  const v4d g174_0 = q3*g50_0;
  const v4d g174_1 = -p50*e3;
  const v4d g175_0 = q2*g50_0 - p50*e2;
  const v4d g176_0 = q1*g50_0 - p50*e1;
  const v4d g177_0 = q8*g52_0;
  const v4d g177_2 = q8*g52_2 - p52*e8;
  const v4d g178_0 = q7*g52_0;
  const v4d g178_2 = q7*g52_2 - p52*e7;
  const v4d g179_0 = q8*g53_0;
  const v4d g179_2 = q8*g53_2 - p53*e8;
  const v4d g180_0 = q7*g53_0;
  const v4d g180_2 = q7*g53_2 - p53*e7;
  const v4d g181_0 = q7*g54_0;
  const v4d g181_1 = q7*g54_1;
  const v4d g181_2 = -p54*e7;
  const v4d g182_0 = q5*g54_0;
  const v4d g182_1 = q5*g54_1 - p54*e5;
  const v4d g183_0 = q7*g55_0;
  const v4d g183_1 = q7*g55_1;
  const v4d g183_2 = -p55*e7;
  const v4d g184_0 = q6*g55_0;
  const v4d g184_1 = q6*g55_1;
  const v4d g184_2 = -p55*e6;
  const v4d g185_0 = q5*g55_0;
  const v4d g185_1 = q5*g55_1 - p55*e5;
  const v4d g186_0 = q4*g55_0;
  const v4d g186_1 = q4*g55_1 - p55*e4;
  const v4d g187_0 = q7*g56_0;
  const v4d g187_1 = q7*g56_1;
  const v4d g187_2 = -p56*e7;
  const v4d g188_0 = q6*g56_0;
  const v4d g188_1 = q6*g56_1;
  const v4d g188_2 = -p56*e6;
  const v4d g189_0 = q5*g56_0;
  const v4d g189_1 = q5*g56_1 - p56*e5;
  const v4d g190_0 = q4*g56_0;
  const v4d g190_1 = q4*g56_1 - p56*e4;
  const v4d g191_0 = q3*g56_0;
  const v4d g191_1 = q3*g56_1 - p56*e3;
  const v4d g192_0 = q8*g57_0;
  const v4d g192_2 = -p57*e8;
  const v4d g193_0 = q7*g57_0;
  const v4d g193_2 = -p57*e7;
  const v4d g194_0 = q6*g57_0;
  const v4d g194_2 = -p57*e6;
  const v4d g195_0 = q5*g57_0;
  const v4d g195_1 = -p57*e5;
  const v4d g196_0 = q4*g57_0;
  const v4d g196_1 = -p57*e4;
  const v4d g197_0 = q3*g57_0;
  const v4d g197_1 = -p57*e3;
  const v4d g198_0 = q2*g57_0 - p57*e2;
  const v4d g199_0 = q7*g58_0;
  const v4d g199_2 = -p58*e7;
  const v4d g200_0 = q6*g58_0;
  const v4d g200_2 = -p58*e6;
  const v4d g201_0 = q5*g58_0;
  const v4d g201_1 = -p58*e5;
  const v4d g202_0 = q4*g58_0;
  const v4d g202_1 = -p58*e4;
  const v4d g203_0 = q3*g58_0;
  const v4d g203_1 = -p58*e3;
  const v4d g204_0 = q2*g58_0 - p58*e2;
  const v4d g205_0 = q1*g58_0 - p58*e1;
  const v4d g206_0 = q8*g59_0;
  const v4d g206_2 = -p59*e8;
  const v4d g207_0 = q7*g59_0;
  const v4d g207_2 = -p59*e7;
  const v4d g208_0 = q6*g59_0;
  const v4d g208_2 = -p59*e6;
  const v4d g209_0 = q5*g59_0;
  const v4d g209_1 = -p59*e5;
  const v4d g210_0 = q4*g59_0;
  const v4d g210_1 = -p59*e4;
  const v4d g211_0 = q3*g59_0;
  const v4d g211_1 = -p59*e3;
  const v4d g212_0 = q2*g59_0 - p59*e2;
  const v4d g213_0 = q1*g59_0 - p59*e1;
  const v4d g214_0 = q0*g59_0 - p59*e0;
  const v4d g215_3 = q10*g60_3 - p60*e10;
  const v4d g216_3 = q10*g61_3 - p61*e10;
  const v4d g217_3 = q10*g62_3 - p62*e10;
  const v4d g218_3 = q10*g63_3 - p63*e10;
  const v4d g219_3 = q9*g63_3 - p63*e9;
  const v4d g220_2 = q9*g64_2;
  const v4d g220_3 = q9*g64_3 - p64*e9;
  const v4d g221_2 = q8*g66_2 - p66*e8;
  const v4d g222_2 = q8*g67_2 - p67*e8;
  const v4d g223_2 = q8*g68_2 - p68*e8;
  const v4d g224_2 = q8*g69_2 - p69*e8;
  const v4d g225_2 = q7*g69_2 - p69*e7;
  const v4d g226_2 = q8*g70_2 - p70*e8;
  const v4d g227_2 = q8*g71_2 - p71*e8;
  const v4d g228_2 = q8*g72_2 - p72*e8;
  const v4d g229_2 = q7*g72_2 - p72*e7;
  const v4d g230_2 = q8*g73_2 - p73*e8;
  const v4d g231_2 = q8*g74_2 - p74*e8;
  const v4d g232_2 = q7*g74_2 - p74*e7;
  const v4d g233_2 = q8*g75_2 - p75*e8;
  const v4d g234_2 = q7*g75_2 - p75*e7;
  const v4d g235_2 = q6*g75_2 - p75*e6;
  const v4d g236_0 = q1*g213_0 - p213*e1;
  const v4d g237_0 = q1*g214_0 - p214*e1;
  const v4d g238_0 = q0*g214_0 - p214*e0;
  const v4d g239_3 = q10*g215_3 - p215*e10;
  const v4d g240_3 = q10*g216_3 - p216*e10;
  const v4d g241_3 = q10*g217_3 - p217*e10;
  const v4d g242_3 = q10*g218_3 - p218*e10;
  const v4d g243_3 = q9*g219_3 - p219*e9;
  const v4d g244_2 = q8*g221_2 - p221*e8;
  const v4d g245_2 = q8*g223_2 - p223*e8;
  const v4d g246_2 = q8*g224_2 - p224*e8;
  const v4d g247_2 = q8*g225_2 - p225*e8;
  const v4d g248_2 = q7*g225_2 - p225*e7;
  const v4d g249_2 = q8*g226_2 - p226*e8;
  const v4d g250_2 = q8*g227_2 - p227*e8;
  const v4d g251_2 = q8*g228_2 - p228*e8;
  const v4d g252_2 = q8*g229_2 - p229*e8;
  const v4d g253_2 = q7*g229_2 - p229*e7;
  const v4d g254_2 = q8*g230_2 - p230*e8;
  const v4d g255_2 = q8*g231_2 - p231*e8;
  const v4d g256_2 = q8*g232_2 - p232*e8;
  const v4d g257_2 = q7*g232_2 - p232*e7;
  const v4d g258_2 = q8*g233_2 - p233*e8;
  const v4d g259_2 = q8*g234_2 - p234*e8;
  const v4d g260_2 = q7*g234_2 - p234*e7;
  const v4d g261_2 = q8*g235_2 - p235*e8;
  const v4d g262_2 = q7*g235_2 - p235*e7;
  const v4d g263_2 = q6*g235_2 - p235*e6;
  const v4d g264_0 = q1*g237_0 - p237*e1;
  const v4d g265_0 = q1*g238_0 - p238*e1;
  const v4d g266_0 = q0*g238_0 - p238*e0;
  const v4d g267_3 = q10*g239_3 - p239*e10;
  const v4d g268_3 = q10*g240_3 - p240*e10;
  const v4d g269_3 = q10*g241_3 - p241*e10;
  const v4d g270_3 = q10*g243_3 - p243*e10;
  const v4d g271_3 = q9*g243_3 - p243*e9;
  const v4d g272_2 = q8*g244_2 - p244*e8;
  const v4d g273_2 = q8*g246_2 - p246*e8;
  const v4d g274_2 = q8*g247_2 - p247*e8;
  const v4d g275_2 = q8*g248_2 - p248*e8;
  const v4d g276_2 = q7*g248_2 - p248*e7;
  const v4d g277_2 = q8*g249_2 - p249*e8;
  const v4d g278_2 = q8*g250_2 - p250*e8;
  const v4d g279_2 = q8*g251_2 - p251*e8;
  const v4d g280_2 = q8*g252_2 - p252*e8;
  const v4d g281_2 = q8*g253_2 - p253*e8;
  const v4d g282_2 = q7*g253_2 - p253*e7;
  const v4d g283_2 = q8*g254_2 - p254*e8;
  const v4d g284_2 = q8*g255_2 - p255*e8;
  const v4d g285_2 = q8*g256_2 - p256*e8;
  const v4d g286_2 = q8*g257_2 - p257*e8;
  const v4d g287_2 = q7*g257_2 - p257*e7;
  const v4d g288_2 = q8*g258_2 - p258*e8;
  const v4d g289_2 = q8*g259_2 - p259*e8;
  const v4d g290_2 = q8*g260_2 - p260*e8;
  const v4d g291_2 = q7*g260_2 - p260*e7;
  const v4d g292_2 = q8*g261_2 - p261*e8;
  const v4d g293_2 = q8*g262_2 - p262*e8;
  const v4d g294_2 = q7*g262_2 - p262*e7;
  const v4d g295_2 = q8*g263_2 - p263*e8;
  const v4d g296_2 = q7*g263_2 - p263*e7;
  const v4d g297_2 = q6*g263_2 - p263*e6;
  const v4d g298_0 = q1*g265_0 - p265*e1;
  const v4d g299_0 = q1*g266_0 - p266*e1;
  const v4d g300_0 = q0*g266_0 - p266*e0;
  const v4d g301_3 = q10*g267_3 - p267*e10;
  const v4d g302_3 = q10*g269_3 - p269*e10;
  const v4d g303_3 = q10*g270_3 - p270*e10;
  const v4d g304_3 = q10*g271_3 - p271*e10;
  const v4d g305_3 = q9*g271_3 - p271*e9;
  const v4d g306_3 = q10*g301_3 - p301*e10;
  const v4d g307_3 = q9*g305_3 - p305*e9;
  const v4d g308_3 = q10*g306_3 - p306*e10;
  const v4d g309_3 = q9*g307_3 - p307*e9;
  { const v4d a0 = (0.22246074407119382*e_len + -0.17397440241978457*g48_0 + -0.021796873857241789*g49_0 + 0.017243827661874302*g176_0) + (0.10652121621103681*g10_0 + 0.047479729987193207*g169_0 + 0.10514343634087572*g163_0); const v4d a1 = (-0.17397440241978457*g48_1 + 0.047479729987193207*g169_1 + 0.10514343634087572*g163_1) + (-0.021603016385337119*g6_1 + -0.0054898942249615541*g114_1 + 0.018825224428917892*g119_1);
    moment_arm[0 * kMaxElements + 0] = a0[0]; moment_arm[1 * kMaxElements + 0] = a0[1]; moment_arm[2 * kMaxElements + 0] = a0[2]; moment_arm[3 * kMaxElements + 0] = a1[0]; moment_arm[4 * kMaxElements + 0] = a1[1]; moment_arm[5 * kMaxElements + 0] = a1[2]; L[0] = a0[3] + a1[3]; }
  { const v4d a0 = (0.21026052016027599*e_len + -0.065772899622210043*g9_0 + -0.01916175085425631*g156_0 + -0.018361952601638219*g172_0) + (0.10990893067475514*g10_0 + 0.012028798304616435*g49_0 + 0.012611314016633601*g146_0 + -0.0071699327251612995*g135_0); const v4d a1 = (0.018911554866392944*g29_1 + 0.012611314016633601*g146_1 + -0.018361952601638219*g172_1) + (-0.01916175085425631*g156_1 + -0.0090523069118706896*g109_1 + -0.0071699327251612995*g135_1);
    moment_arm[0 * kMaxElements + 1] = a0[0]; moment_arm[1 * kMaxElements + 1] = a0[1]; moment_arm[2 * kMaxElements + 1] = a0[2]; moment_arm[3 * kMaxElements + 1] = a1[0]; moment_arm[4 * kMaxElements + 1] = a1[1]; moment_arm[5 * kMaxElements + 1] = a1[2]; L[1] = a0[3] + a1[3]; }
  { const v4d a0 = (0.18279398549146325*e_len + -0.057514618943145572*g9_0 + -0.0052466437490747975*g48_0 + -0.017130099541968698*g195_0 + 0.016184004375372336*g42_0) + (0.11082608079356703*g10_0 + 0.056721290766815625*g139_0 + 0.042584479922797201*g140_0 + -0.031236524592532681*g173_0); const v4d a1 = (0.056721290766815625*g139_1 + -0.038657538918052743*g99_1 + -0.017130099541968698*g195_1) + (-0.0052466437490747975*g48_1 + 0.042584479922797201*g140_1 + -0.031236524592532681*g173_1);
    moment_arm[0 * kMaxElements + 2] = a0[0]; moment_arm[1 * kMaxElements + 2] = a0[1]; moment_arm[2 * kMaxElements + 2] = a0[2]; moment_arm[3 * kMaxElements + 2] = a1[0]; moment_arm[4 * kMaxElements + 2] = a1[1]; moment_arm[5 * kMaxElements + 2] = a1[2]; L[2] = a0[3] + a1[3]; }
  { const v4d a0 = (0.16585944957338097*e_len + -0.051317667489766468*g9_0 + 0.0057522690779035776*g162_0 + 0.07941763528513579*g139_0 + 0.024846472386074517*g41_0) + (0.11750746984573869*g10_0 + -0.017701533898999953*g169_0 + 0.039533713591384384*g146_0 + -0.044933520196313047*g173_0); const v4d a1 = (0.005575132777524805*g34_1 + 0.0057522690779035776*g162_1 + 0.039533713591384384*g146_1 + 0.015276464872532567*g120_1 + -0.044933520196313047*g173_1) + (-0.017701533898999953*g169_1 + -0.0092056678499012595*g109_1 + 0.040696799172899041*g29_1 + 0.07941763528513579*g139_1 + 0.024846472386074517*g41_1);
    moment_arm[0 * kMaxElements + 3] = a0[0]; moment_arm[1 * kMaxElements + 3] = a0[1]; moment_arm[2 * kMaxElements + 3] = a0[2]; moment_arm[3 * kMaxElements + 3] = a1[0]; moment_arm[4 * kMaxElements + 3] = a1[1]; moment_arm[5 * kMaxElements + 3] = a1[2]; L[3] = a0[3] + a1[3]; }
  { const v4d a0 = (0.15551882560270572*e_len + -0.037496211384297408*g9_0 + 0.051118807151055129*g135_0 + -0.079495142751239797*g205_0 + -0.020870639653316061*g169_0 + 0.053298975555615115*g202_0 + 0.0017647980279305116*g210_0 + 0.025705026784643814*g42_0) + (0.11629101791371896*g10_0 + -0.015362851988856419*g175_0 + 0.0091262259819420398*g146_0 + 0.092492186694292933*g40_0 + 0.062797885175314136*g203_0 + 0.0096192451570779464*g163_0 + -0.024717489010308027*g196_0 + 0.038252088423292981*g140_0); const v4d a1 = (-0.091535770350833906*g114_1 + 0.051118807151055129*g135_1 + -0.0072705307529724421*g99_1 + 0.092492186694292933*g40_1 + 0.062797885175314136*g203_1 + 0.0096192451570779464*g163_1 + -0.024717489010308027*g196_1 + 0.079954906548259277*g29_1) + (-0.016676519666206941*g113_1 + 0.0091262259819420398*g146_1 + -0.030027939779723959*g34_1 + -0.020870639653316061*g169_1 + 0.053298975555615115*g202_1 + 0.0017647980279305116*g210_1 + 0.038252088423292981*g140_1);
    moment_arm[0 * kMaxElements + 4] = a0[0]; moment_arm[1 * kMaxElements + 4] = a0[1]; moment_arm[2 * kMaxElements + 4] = a0[2]; moment_arm[3 * kMaxElements + 4] = a1[0]; moment_arm[4 * kMaxElements + 4] = a1[1]; moment_arm[5 * kMaxElements + 4] = a1[2]; L[4] = a0[3] + a1[3]; }
  { const v4d a0 = (0.17432586365658245*e_len + -0.10401599985725052*g41_0 + -0.015462966321303194*g157_0 + 0.12354466197761124*g140_0 + -0.050381295094664297*g174_0 + 0.059595547589872039*g204_0) + (0.13011349892737548*g10_0 + -0.0053870120671289474*g146_0 + -0.14210376358598736*g205_0 + 0.03527483040980843*g42_0 + 0.040417334504798605*g139_0); const v4d a1 = (-0.0045627893525915083*g34_1 + -0.0053870120671289474*g146_1 + 0.041082416192793222*g29_1 + -0.050381295094664297*g174_1) + (-0.10401599985725052*g41_1 + -0.015462966321303194*g157_1 + 0.12354466197761124*g140_1 + 0.040417334504798605*g139_1);
    moment_arm[0 * kMaxElements + 5] = a0[0]; moment_arm[1 * kMaxElements + 5] = a0[1]; moment_arm[2 * kMaxElements + 5] = a0[2]; moment_arm[3 * kMaxElements + 5] = a1[0]; moment_arm[4 * kMaxElements + 5] = a1[1]; moment_arm[5 * kMaxElements + 5] = a1[2]; L[5] = a0[3] + a1[3]; }
  { const v4d a0 = (0.17354791902314778*e_len + 0.013408128854029177*g9_0 + -0.056726407379885192*g135_0 + 0.045526317882212543*g146_0 + 0.020397862443760448*g168_0 + 0.070186864071128396*g213_0 + 0.048003525005164666*g140_0) + (0.12764741526954557*g10_0 + -0.069335818730652518*g41_0 + 0.076079660637371579*g202_0 + 0.021578506612089314*g174_0 + -0.0065164673848290442*g196_0 + 0.018074230330557186*g55_0 + 0.067229347784152696*g197_0); const v4d a1 = (0.080969450390405193*g29_1 + -0.056726407379885192*g135_1 + 0.045526317882212543*g146_1 + 0.021578506612089314*g174_1 + -0.0065164673848290442*g196_1 + 0.048003525005164666*g140_1 + -0.022622018235106359*g114_1) + (-0.069335818730652518*g41_1 + 0.076079660637371579*g202_1 + -0.014117972471012026*g109_1 + 0.020397862443760448*g168_1 + 0.018074230330557186*g55_1 + 0.067229347784152696*g197_1);
    moment_arm[0 * kMaxElements + 6] = a0[0]; moment_arm[1 * kMaxElements + 6] = a0[1]; moment_arm[2 * kMaxElements + 6] = a0[2]; moment_arm[3 * kMaxElements + 6] = a1[0]; moment_arm[4 * kMaxElements + 6] = a1[1]; moment_arm[5 * kMaxElements + 6] = a1[2]; L[6] = a0[3] + a1[3]; }
  { const v4d a0 = (0.15614502337434827*e_len + 0.0094408177858511712*g157_0 + -0.082465168988130083*g186_0 + 0.043211051814588251*g9_0 + 0.075960514060908341*g57_0 + -0.044599864004499785*g145_0) + (0.098964330422012678*g10_0 + 0.08576962870910039*g40_0 + -0.034177835430486934*g205_0 + -0.064634848011231871*g203_0 + -0.10823294190694197*g190_0 + 0.065779182399365727*g212_0); const v4d a1 = (0.0094408177858511712*g157_1 + -0.082465168988130083*g186_1 + -0.064634848011231871*g203_1 + -0.044599864004499785*g145_1) + (0.08576962870910039*g40_1 + -0.07802488657220312*g6_1 + -0.10823294190694197*g190_1 + 0.0085760483757760415*g120_1);
    moment_arm[0 * kMaxElements + 7] = a0[0]; moment_arm[1 * kMaxElements + 7] = a0[1]; moment_arm[2 * kMaxElements + 7] = a0[2]; moment_arm[3 * kMaxElements + 7] = a1[0]; moment_arm[4 * kMaxElements + 7] = a1[1]; moment_arm[5 * kMaxElements + 7] = a1[2]; L[7] = a0[3] + a1[3]; }
  { const v4d a0 = (0.16051097055086244*e_len + 0.069353825315151121*g197_0 + -0.11613674452135002*g191_0 + -0.070646318150728138*g55_0 + 0.20624831301111493*g56_0 + 0.15652786491214196*g135_0 + 0.015848806076279077*g147_0) + (0.023098742006691986*g157_0 + 0.035936485015033777*g163_0 + 0.20238666610418451*g40_0 + 0.058001342692012986*g9_0 + 0.091941053995583583*g213_0 + 0.1249603785372396*g190_0 + 0.012033751491067482*g212_0); const v4d a1 = (0.023098742006691986*g157_1 + 0.035936485015033777*g163_1 + -0.11613674452135002*g191_1 + -0.070646318150728138*g55_1 + 0.01742564484579456*g118_1 + 0.1249603785372396*g190_1) + (0.069353825315151121*g197_1 + -0.11704427969175064*g6_1 + 0.20238666610418451*g40_1 + 0.20624831301111493*g56_1 + 0.15652786491214196*g135_1 + -0.03148795561900939*g114_1);
    moment_arm[0 * kMaxElements + 8] = a0[0]; moment_arm[1 * kMaxElements + 8] = a0[1]; moment_arm[2 * kMaxElements + 8] = a0[2]; moment_arm[3 * kMaxElements + 8] = a1[0]; moment_arm[4 * kMaxElements + 8] = a1[1]; moment_arm[5 * kMaxElements + 8] = a1[2]; L[8] = a0[3] + a1[3]; }
  { const v4d a0 = (0.18713535237539652*e_len + -0.00038493936866123614*g57_0 + 0.021146910114443043*g146_0 + -0.058526032969397471*g8_0 + -0.05563251299327622*g212_0 + -0.057816006447952685*g186_0 + 0.075870687777054038*g213_0 + -0.093638393083720461*g210_0 + 0.034762208751429262*g10_0) + (0.089524822951084979*g9_0 + -0.013770371024093805*g198_0 + -0.11082584050482643*g55_0 + 0.04297172782230347*g56_0 + 0.027598492553906177*g169_0 + 0.065992029785438416*g139_0 + -0.018671311836654086*g162_0 + 0.039037183370849854*g173_0); const v4d a1 = (-0.10414701415227598*g6_1 + -0.11082584050482643*g55_1 + 0.027598492553906177*g169_1 + 0.065992029785438416*g139_1 + -0.018671311836654086*g162_1 + -0.093638393083720461*g210_1) + (0.021146910114443043*g146_1 + 0.04297172782230347*g56_1 + -0.057816006447952685*g186_1 + 0.0093919196694058297*g120_1 + 0.0066026144179690688*g118_1 + 0.039037183370849854*g173_1);
    moment_arm[0 * kMaxElements + 9] = a0[0]; moment_arm[1 * kMaxElements + 9] = a0[1]; moment_arm[2 * kMaxElements + 9] = a0[2]; moment_arm[3 * kMaxElements + 9] = a1[0]; moment_arm[4 * kMaxElements + 9] = a1[1]; moment_arm[5 * kMaxElements + 9] = a1[2]; L[9] = a0[3] + a1[3]; }
  { const v4d a0 = (0.22997019590113618*e_len + 0.016726279108780641*g57_0 + 0.013447221977497162*g204_0 + 0.0077326508222148975*g191_0 + 0.088087283944449465*g9_0 + 0.0028792117941211794*g139_0 + -0.068596093885086931*g8_0) + (-0.0091653492045755385*g47_0 + 0.011060898435236135*g174_0 + 0.081712767724064481*g173_0 + 0.049641376296838138*g49_0 + -0.050091845294455234*g58_0 + 0.088784715833056541*g10_0 + 0.038245957475780031*g59_0); const v4d a1 = (-0.0091653492045755385*g47_1 + 0.011060898435236135*g174_1 + 0.081712767724064481*g173_1 + -0.036425611880191361*g119_1 + -0.15014023831847031*g113_1 + 0.14431837163689162*g29_1) + (0.055767935402062277*g98_1 + 0.11973853525037093*g28_1 + 0.0077326508222148975*g191_1 + 0.089169675547331656*g99_1 + 0.0028792117941211794*g139_1);
    moment_arm[0 * kMaxElements + 10] = a0[0]; moment_arm[1 * kMaxElements + 10] = a0[1]; moment_arm[2 * kMaxElements + 10] = a0[2]; moment_arm[3 * kMaxElements + 10] = a1[0]; moment_arm[4 * kMaxElements + 10] = a1[1]; moment_arm[5 * kMaxElements + 10] = a1[2]; L[10] = a0[3] + a1[3]; }
  { const v4d a0 = (0.21118652424677534*e_len + 0.0074624717451287478*g236_0 + -0.096982796093105825*g9_0 + -0.0059467821005661191*g8_0) + (0.019095354019034602*g58_0 + 0.0750922783555526*g10_0 + 0.013344904258677485*g42_0);
    moment_arm[0 * kMaxElements + 11] = a0[0]; moment_arm[1 * kMaxElements + 11] = a0[1]; moment_arm[2 * kMaxElements + 11] = a0[2]; L[11] = a0[3]; }
  { const v4d a0 = (0.19150832079079014*e_len + 0.9373156358455178*g214_0 + -0.958807817689456*g264_0 + -9.8491388785351539*g299_0 + -1.5598775142826036*g298_0 + -1.1372357526526498*g266_0 + 0.0087776105248512561*g42_0) + (0.45920791231534119*g58_0 + -12.934237738490724*g265_0 + -2.4629293139413329*g300_0 + -0.0081404387184613146*g8_0 + -0.014693924892157491*g176_0 + -5.1680400523381333*g237_0 + 1.4232548505098799*g238_0);
    moment_arm[0 * kMaxElements + 12] = a0[0]; moment_arm[1 * kMaxElements + 12] = a0[1]; moment_arm[2 * kMaxElements + 12] = a0[2]; L[12] = a0[3]; }
  { const v4d a0 = (0.15464111361414362*e_len + 0.0065800035192562474*g8_0 + -0.11156622304713992*g9_0 + 0.0030172375164596202*g205_0 + -0.12214170545327131*g168_0 + -0.017542368153626822*g214_0 + 0.067256461589667887*g202_0 + 0.20589937348404608*g41_0) + (-0.019853064056665287*g47_0 + -0.15636264334654534*g157_0 + -0.003586058917923211*g189_0 + -0.044592830010987489*g170_0 + -0.008428273720961596*g54_0 + -0.010291669653858073*g57_0 + 0.034910630207857216*g197_0 + -0.11859120877784807*g140_0); const v4d a1 = (-0.019853064056665287*g47_1 + 0.021902353182898949*g99_1 + 0.084186194810352249*g29_1 + -0.12214170545327131*g168_1 + -0.016465566074981661*g33_1 + 0.067256461589667887*g202_1 + 0.20589937348404608*g41_1) + (0.038852866730379278*g35_1 + -0.15636264334654534*g157_1 + -0.003586058917923211*g189_1 + -0.008428273720961596*g54_1 + 0.1346931492260324*g6_1 + 0.034910630207857216*g197_1 + -0.11859120877784807*g140_1);
    moment_arm[0 * kMaxElements + 13] = a0[0]; moment_arm[1 * kMaxElements + 13] = a0[1]; moment_arm[2 * kMaxElements + 13] = a0[2]; moment_arm[3 * kMaxElements + 13] = a1[0]; moment_arm[4 * kMaxElements + 13] = a1[1]; moment_arm[5 * kMaxElements + 13] = a1[2]; L[13] = a0[3] + a1[3]; }
  { const v4d a0 = (0.099842110364020714*e_len + 0.1747941838465466*g41_0 + 0.0056467179212739936*g57_0 + -0.068343112387873897*g209_0 + 0.021565777583382045*g212_0 + -0.05813382529811166*g54_0 + -0.012340346138808153*g46_0 + -0.067259700274456727*g153_0 + 0.012600233045902982*g42_0) + (-0.11258210003988786*g9_0 + -0.045612454432381308*g190_0 + -0.0097082764584771955*g173_0 + -0.085420634480453686*g140_0 + 0.065907720107627465*g156_0 + -0.18808334018529246*g168_0 + -0.061699004625700896*g170_0 + 0.037573866963242677*g40_0 + -0.15901321282028485*g157_0); const v4d a1 = (0.1747941838465466*g41_1 + 0.058152419657087243*g7_1 + 0.1263506729744977*g29_1 + -0.068343112387873897*g209_1 + -0.096590784830142676*g114_1 + 0.065907720107627465*g156_1 + -0.18808334018529246*g168_1 + -0.067259700274456727*g153_1 + -0.15901321282028485*g157_1) + (0.088417860100536191*g6_1 + -0.045612454432381308*g190_1 + -0.0097082764584771955*g173_1 + -0.085420634480453686*g140_1 + -0.026299994249395577*g33_1 + -0.05813382529811166*g54_1 + -0.012340346138808153*g46_1 + 0.037573866963242677*g40_1);
    moment_arm[0 * kMaxElements + 14] = a0[0]; moment_arm[1 * kMaxElements + 14] = a0[1]; moment_arm[2 * kMaxElements + 14] = a0[2]; moment_arm[3 * kMaxElements + 14] = a1[0]; moment_arm[4 * kMaxElements + 14] = a1[1]; moment_arm[5 * kMaxElements + 14] = a1[2]; L[14] = a0[3] + a1[3]; }
  { const v4d a0 = (0.096338062607615002*e_len + -0.024692482651957538*g10_0 + -0.0058852157578615748*g140_0 + -0.017267146071609004*g182_0 + 0.0014839685103268088*g156_0 + -0.033630803832415866*g139_0 + -0.024145762004686308*g213_0 + -0.013623118462557673*g146_0 + 0.039915100641647619*g190_0 + -0.034690494523089303*g175_0 + -0.026244783400739279*g173_0 + 0.025171460925603517*g46_0) + (0.079716582170205094*g9_0 + -0.010702414196320351*g48_0 + 0.013961393153414891*g203_0 + 0.022262474979491013*g59_0 + -0.017284179952461835*g163_0 + -0.025365224675193049*g55_0 + 0.051810244498299629*g168_0 + 0.001179310402061155*g57_0 + 0.038832043011950756*g49_0 + -4.5346726982943248e-05*g39_0 + 0.017221467208633632*g170_0); const v4d a1 = (0.034302162985057109*g118_1 + -0.010702414196320351*g48_1 + 0.013961393153414891*g203_1 + 0.17071590755214888*g34_1 + 0.0014839685103268088*g156_1 + -0.097666615731100886*g6_1 + -0.033630803832415866*g139_1 + -0.025365224675193049*g55_1 + -0.013623118462557673*g146_1 + -4.5346726982943248e-05*g39_1 + -0.026244783400739279*g173_1 + 0.025171460925603517*g46_1) + (-0.078828435383367784*g119_1 + -0.0058852157578615748*g140_1 + -0.017267146071609004*g182_1 + 0.0084458519073338373*g5_1 + -0.028931848850936814*g98_1 + -0.017284179952461835*g163_1 + 0.074792200859517308*g113_1 + 0.051810244498299629*g168_1 + 0.039915100641647619*g190_1 + 0.024583758469541316*g109_1 + -0.12182189726791123*g28_1);
    moment_arm[0 * kMaxElements + 15] = a0[0]; moment_arm[1 * kMaxElements + 15] = a0[1]; moment_arm[2 * kMaxElements + 15] = a0[2]; moment_arm[3 * kMaxElements + 15] = a1[0]; moment_arm[4 * kMaxElements + 15] = a1[1]; moment_arm[5 * kMaxElements + 15] = a1[2]; L[15] = a0[3] + a1[3]; }
  { const v4d a0 = (0.10891865504685884*e_len + -0.0336176651204654*g210_0 + -0.039217570324710439*g163_0 + -0.12396650280104698*g56_0 + -0.061330311109780093*g202_0 + -0.015680437745752243*g168_0 + -0.032027532629672666*g190_0 + 0.011782572050757148*g173_0) + (0.1142055527861098*g9_0 + 0.014093137518497292*g195_0 + 0.082239906384849765*g191_0 + -0.016899341398922605*g138_0 + 0.021537025832189985*g172_0 + 0.010551061036897673*g144_0 + 0.022795687137870349*g203_0 + -0.0061867498793988594*g40_0); const v4d a1 = (0.11260477439907911*g33_1 + 0.014093137518497292*g195_1 + 0.082239906384849765*g191_1 + -0.12396650280104698*g56_1 + -0.061330311109780093*g202_1 + 0.021537025832189985*g172_1 + 0.010551061036897673*g144_1 + 0.022795687137870349*g203_1 + 0.013627921205011207*g34_1 + -0.0061867498793988594*g40_1) + (-0.0336176651204654*g210_1 + -0.039217570324710439*g163_1 + -0.037554919116053159*g6_1 + -0.016899341398922605*g138_1 + -0.034180315706473521*g113_1 + -0.015680437745752243*g168_1 + -0.032027532629672666*g190_1 + -0.066076692002577223*g118_1 + 0.011782572050757148*g173_1);
    moment_arm[0 * kMaxElements + 16] = a0[0]; moment_arm[1 * kMaxElements + 16] = a0[1]; moment_arm[2 * kMaxElements + 16] = a0[2]; moment_arm[3 * kMaxElements + 16] = a1[0]; moment_arm[4 * kMaxElements + 16] = a1[1]; moment_arm[5 * kMaxElements + 16] = a1[2]; L[16] = a0[3] + a1[3]; }
  { const v4d a0 = (0.084975578380761724*e_len + 0.046028982826872587*g210_0 + 0.083370415991086549*g55_0 + 0.13655543484191723*g161_0 + -0.09191246222465066*g174_0 + 0.069660853353472399*g153_0 + 0.054049882728924636*g211_0 + 0.036169535453956438*g50_0) + (0.14044918225618847*g9_0 + -0.10957348099938231*g202_0 + 0.020853974566572772*g59_0 + 0.0040144568227287302*g130_0 + 0.026869723692898171*g49_0 + 0.032681810077809917*g134_0 + 0.0083861547046391559*g198_0); const v4d a1 = (0.0012289372780983443*g109_1 + -0.10957348099938231*g202_1 + 0.13655543484191723*g161_1 + -0.09191246222465066*g174_1 + 0.069660853353472399*g153_1 + 0.032681810077809917*g134_1) + (0.046028982826872587*g210_1 + 0.083370415991086549*g55_1 + 0.0040144568227287302*g130_1 + -0.060319597042402535*g24_1 + 0.034268781896970399*g118_1 + 0.054049882728924636*g211_1);
    moment_arm[0 * kMaxElements + 17] = a0[0]; moment_arm[1 * kMaxElements + 17] = a0[1]; moment_arm[2 * kMaxElements + 17] = a0[2]; moment_arm[3 * kMaxElements + 17] = a1[0]; moment_arm[4 * kMaxElements + 17] = a1[1]; moment_arm[5 * kMaxElements + 17] = a1[2]; L[17] = a0[3] + a1[3]; }
  { const v4d a0 = (0.10155260199017856*e_len + 0.0079934236473572819*g210_0 + 0.0061048046074261867*g8_0 + -0.022784281760536085*g56_0 + 0.011636169470080029*g170_0 + 0.062575097147943418*g59_0) + (0.14650096957019659*g9_0 + 0.014489304444940104*g189_0 + -0.059980981583356713*g163_0 + -0.076970423374514277*g213_0 + 0.036896597693293287*g173_0); const v4d a1 = (0.057126466504868904*g33_1 + 0.014489304444940104*g189_1 + -0.022784281760536085*g56_1 + -0.015992425008692638*g6_1) + (0.0079934236473572819*g210_1 + -0.059980981583356713*g163_1 + 0.036896597693293287*g173_1 + 0.018439905852401781*g5_1);
    moment_arm[0 * kMaxElements + 18] = a0[0]; moment_arm[1 * kMaxElements + 18] = a0[1]; moment_arm[2 * kMaxElements + 18] = a0[2]; moment_arm[3 * kMaxElements + 18] = a1[0]; moment_arm[4 * kMaxElements + 18] = a1[1]; moment_arm[5 * kMaxElements + 18] = a1[2]; L[18] = a0[3] + a1[3]; }
  { const v4d a0 = (0.13731317773087515*e_len + 0.30465724460828009*g41_0 + 0.032758810704581483*g213_0 + 0.00018587171079035138*g157_0 + 0.035559425787132268*g47_0 + 0.032279348595986593*g198_0 + -0.051700542159605713*g9_0 + 0.016545235604132024*g205_0 + 0.0041948972450159914*g49_0 + -0.0020676226851716151*g168_0 + -0.10191199857224678*g145_0 + 0.010525354787538275*g189_0 + -0.039749552449529275*g57_0 + 0.011081220857482799*g211_0 + -0.021142593304816357*g40_0 + -0.081213816365594979*g8_0) + (0.074028466166596849*g58_0 + -0.0096691284617856973*g186_0 + 0.080266119858019194*g10_0 + 0.013510619389679382*g144_0 + 0.091177936557387249*g139_0 + -0.067553973825482158*g55_0 + 0.01322038518928554*g138_0 + 0.034212872912609778*g42_0 + -0.023450418578181368*g147_0 + 0.049030105338850057*g134_0 + 0.027673178391786509*g212_0 + 0.018662064968993034*g156_0 + -0.15278982412628864*g135_0 + -0.16311608049819057*g140_0 + 0.038851763692688245*g202_0); const v4d a1 = (0.30465724460828009*g41_1 + 0.067115079838917041*g114_1 + 0.00018587171079035138*g157_1 + 0.022432832174905416*g120_1 + 0.091177936557387249*g139_1 + -0.067553973825482158*g55_1 + 0.01322038518928554*g138_1 + 0.049030105338850057*g134_1 + 0.010525354787538275*g189_1 + -0.033717928771129627*g118_1 + -0.15278982412628864*g135_1 + -0.16311608049819057*g140_1 + 0.038851763692688245*g202_1 + -0.078783806781537138*g99_1) + (-0.0096691284617856973*g186_1 + -0.045347346674259451*g6_1 + 0.013510619389679382*g144_1 + 0.035559425787132268*g47_1 + 0.01508775640821786*g98_1 + 0.0097729837087440364*g5_1 + -0.0020676226851716151*g168_1 + -0.10191199857224678*g145_1 + 0.018662064968993034*g156_1 + 0.2856311329774916*g34_1 + 0.011081220857482799*g211_1 + -0.021142593304816357*g40_1 + -0.19117647053460388*g119_1);
    moment_arm[0 * kMaxElements + 19] = a0[0]; moment_arm[1 * kMaxElements + 19] = a0[1]; moment_arm[2 * kMaxElements + 19] = a0[2]; moment_arm[3 * kMaxElements + 19] = a1[0]; moment_arm[4 * kMaxElements + 19] = a1[1]; moment_arm[5 * kMaxElements + 19] = a1[2]; L[19] = a0[3] + a1[3]; }
  { const v4d a0 = (0.13543436128433203*e_len + 0.011293667097320728*g41_0 + 0.0025276924851304009*g189_0 + -0.25983625551696593*g55_0 + 0.072698779099935412*g161_0 + 0.14987565331530106*g58_0 + 0.09033670796539596*g8_0) + (-0.14890400368634499*g186_0 + 0.13762487796013972*g202_0 + -0.011590680781328964*g174_0 + 0.0061462349317180694*g196_0 + -0.10011960952576011*g210_0 + 0.058383075080690836*g201_0 + 0.049266083330776145*g47_0); const v4d a1 = (-0.14890400368634499*g186_1 + 0.13762487796013972*g202_1 + -0.25441922487198004*g29_1 + -0.011590680781328964*g174_1 + 0.066190114527948749*g114_1 + 0.072698779099935412*g161_1 + -0.17009823777884756*g99_1 + 0.029812362088243755*g35_1) + (0.011293667097320728*g41_1 + -0.083815565587430405*g118_1 + 0.0025276924851304009*g189_1 + -0.25983625551696593*g55_1 + 0.0061462349317180694*g196_1 + -0.10011960952576011*g210_1 + 0.058383075080690836*g201_1 + 0.049266083330776145*g47_1);
    moment_arm[0 * kMaxElements + 20] = a0[0]; moment_arm[1 * kMaxElements + 20] = a0[1]; moment_arm[2 * kMaxElements + 20] = a0[2]; moment_arm[3 * kMaxElements + 20] = a1[0]; moment_arm[4 * kMaxElements + 20] = a1[1]; moment_arm[5 * kMaxElements + 20] = a1[2]; L[20] = a0[3] + a1[3]; }
  { const v4d a0 = (0.11818465275380287*e_len + 0.26702709225792759*g41_0 + -0.15074130591191351*g189_0 + -0.007876496911132725*g203_0 + -0.0048362186515223523*g213_0 + 0.089689843459272889*g58_0 + 0.01451853870383003*g196_0 + -0.0523884597357267*g48_0) + (0.18227086382931246*g186_0 + -0.0054743723133217608*g202_0 + -0.17154588679145416*g140_0 + -0.13931195317758616*g191_0 + 0.16411999983114231*g56_0 + -0.16752781549182885*g185_0 + -0.1277151404886353*g210_0); const v4d a1 = (0.18227086382931246*g186_1 + -0.0054743723133217608*g202_1 + 0.062466218851234726*g7_1 + 0.059779041980324951*g119_1 + -0.13931195317758616*g191_1 + 0.16411999983114231*g56_1 + -0.16752781549182885*g185_1 + 0.11786885394457811*g114_1 + -0.0523884597357267*g48_1) + (0.26702709225792759*g41_1 + -0.15074130591191351*g189_1 + -0.17154588679145416*g140_1 + -0.007876496911132725*g203_1 + 0.14359318832896337*g6_1 + -0.088464693303833372*g118_1 + 0.01451853870383003*g196_1 + -0.1277151404886353*g210_1);
    moment_arm[0 * kMaxElements + 21] = a0[0]; moment_arm[1 * kMaxElements + 21] = a0[1]; moment_arm[2 * kMaxElements + 21] = a0[2]; moment_arm[3 * kMaxElements + 21] = a1[0]; moment_arm[4 * kMaxElements + 21] = a1[1]; moment_arm[5 * kMaxElements + 21] = a1[2]; L[21] = a0[3] + a1[3]; }
  { const v4d a0 = (0.10088639146948085*e_len + 0.20789288478585927*g41_0 + -0.021341526730955372*g204_0 + -0.00097640021551721073*g214_0 + -0.11213567157646993*g140_0 + -0.070111175680489343*g59_0) + (-0.22248603035203127*g55_0 + -0.017282186179597609*g157_0 + -0.2511975308012509*g210_0 + 0.030236753353195433*g161_0 + 0.16798176713309673*g203_0 + 0.015087328693839863*g8_0); const v4d a1 = (-0.22248603035203127*g55_1 + -0.017282186179597609*g157_1 + -0.2511975308012509*g210_1 + -0.11213567157646993*g140_1 + 0.097545249114334459*g6_1 + -0.063884730463396253*g98_1) + (0.20789288478585927*g41_1 + -0.05687517080418316*g118_1 + 0.030236753353195433*g161_1 + 0.055517008513148426*g7_1 + 0.16798176713309673*g203_1);
    moment_arm[0 * kMaxElements + 22] = a0[0]; moment_arm[1 * kMaxElements + 22] = a0[1]; moment_arm[2 * kMaxElements + 22] = a0[2]; moment_arm[3 * kMaxElements + 22] = a1[0]; moment_arm[4 * kMaxElements + 22] = a1[1]; moment_arm[5 * kMaxElements + 22] = a1[2]; L[22] = a0[3] + a1[3]; }
  { const v4d a0 = (0.1184835798779626*e_len + 0.10527829432329201*g41_0 + 0.17114556374750117*g58_0 + -0.066355117788693393*g186_0 + 0.0099430304302552883*g201_0 + 0.024593495816813037*g196_0 + 0.036989843119938165*g9_0 + -0.16237108516079085*g210_0 + 0.012882985366793278*g175_0 + 0.030777722240752432*g8_0 + -0.062904873825790936*g140_0 + -0.012981780477303801*g147_0 + 0.078734595526063614*g197_0 + -0.065940623830421444*g135_0) + (-0.34580564450938284*g55_0 + 0.032456553881387316*g209_0 + -0.056328473628199753*g203_0 + -0.1836991444034996*g57_0 + 0.0057939526952565717*g167_0 + 0.018748694674877088*g146_0 + -0.029553239852742819*g156_0 + -0.13459730158055025*g212_0 + 0.10709013152388444*g56_0 + 0.1858009413020012*g190_0 + -0.043537039901176758*g163_0 + -0.045781895288611082*g214_0 + -0.035331278361946702*g145_0 + 0.014706277680339715*g176_0); const v4d a1 = (-0.34580564450938284*g55_1 + 0.032456553881387316*g209_1 + -0.056328473628199753*g203_1 + -0.083249065152467688*g98_1 + 0.038725274821695445*g120_1 + 0.0099430304302552883*g201_1 + 0.024593495816813037*g196_1 + -0.029553239852742819*g156_1 + 0.11897125326894287*g6_1 + 0.1858009413020012*g190_1 + -0.043537039901176758*g163_1 + -0.035331278361946702*g145_1 + 0.031935149822567052*g5_1) + (0.10527829432329201*g41_1 + 0.019598227546895042*g7_1 + 0.017671167863665613*g114_1 + -0.066355117788693393*g186_1 + -0.086333108767972913*g33_1 + 0.0057939526952565717*g167_1 + 0.018748694674877088*g146_1 + -0.16237108516079085*g210_1 + 0.10709013152388444*g56_1 + -0.062904873825790936*g140_1 + 0.078734595526063614*g197_1 + -0.065940623830421444*g135_1);
    moment_arm[0 * kMaxElements + 23] = a0[0]; moment_arm[1 * kMaxElements + 23] = a0[1]; moment_arm[2 * kMaxElements + 23] = a0[2]; moment_arm[3 * kMaxElements + 23] = a1[0]; moment_arm[4 * kMaxElements + 23] = a1[1]; moment_arm[5 * kMaxElements + 23] = a1[2]; L[23] = a0[3] + a1[3]; }
  { const v4d a0 = (0.12053637336162021*e_len + -0.15801802773887527*g8_0 + 0.21534573631087653*g135_0 + 0.049901898423849934*g176_0 + 0.071541378834269601*g174_0 + -0.11160907554688659*g185_0 + 0.1858986748601146*g145_0 + -0.12827907842620129*g10_0 + -0.082441043458314961*g57_0 + 0.052167930360817252*g147_0) + (-0.044844822932368307*g55_0 + -0.067015053593814738*g161_0 + 0.12305761077496954*g197_0 + 0.034462842543442625*g211_0 + -0.050322023205510706*g54_0 + 0.1044010920989716*g163_0 + 0.01539247339720253*g201_0 + 0.087615272725875867*g203_0 + -0.021674970565319421*g191_0 + 0.013991329317158128*g168_0); const v4d a1 = (-0.044844822932368307*g55_1 + 0.21534573631087653*g135_1 + 0.093325683270520182*g28_1 + 0.034462842543442625*g211_1 + -0.050322023205510706*g54_1 + 0.1044010920989716*g163_1 + -0.046407128441009915*g5_1 + 0.087615272725875867*g203_1 + 0.21737284509896823*g98_1) + (-0.067015053593814738*g161_1 + 0.12305761077496954*g197_1 + -0.14546749307443704*g6_1 + 0.071541378834269601*g174_1 + -0.11160907554688659*g185_1 + 0.1858986748601146*g145_1 + 0.01539247339720253*g201_1 + -0.021674970565319421*g191_1 + 0.013991329317158128*g168_1);
    moment_arm[0 * kMaxElements + 24] = a0[0]; moment_arm[1 * kMaxElements + 24] = a0[1]; moment_arm[2 * kMaxElements + 24] = a0[2]; moment_arm[3 * kMaxElements + 24] = a1[0]; moment_arm[4 * kMaxElements + 24] = a1[1]; moment_arm[5 * kMaxElements + 24] = a1[2]; L[24] = a0[3] + a1[3]; }
  { const v4d a0 = (0.13755286161871955*e_len + -0.15877212727209691*g8_0 + 0.14098380042954425*g174_0 + -0.11462435937333819*g10_0 + 0.1375897031655364*g175_0 + 0.10076521926163376*g205_0 + 0.085041180466403452*g145_0 + 0.005558210319113*g144_0 + -0.15801948479554676*g211_0 + -0.053144460959005733*g42_0 + 0.090571319703571559*g167_0 + 0.075895313062231101*g157_0) + (-0.0085254661663492978*g55_0 + -0.11123337940347686*g161_0 + 0.090260216047120867*g168_0 + -0.0032313691236553659*g135_0 + 0.0068682348127621492*g162_0 + 0.14940317162067368*g134_0 + 0.044126587962926324*g147_0 + -0.034105714546133058*g214_0 + -0.08855498850858351*g191_0 + 0.078673447446575701*g59_0 + 0.067273952807534246*g173_0 + -0.10964760590711198*g40_0); const v4d a1 = (-0.0085254661663492978*g55_1 + -0.54353695444074968*g113_1 + 0.090260216047120867*g168_1 + 0.48546921985477826*g94_1 + 0.035750548485110688*g5_1 + 0.0068682348127621492*g162_1 + -0.1253779286016877*g118_1 + 0.005558210319113*g144_1 + -0.15801948479554676*g211_1 + 0.16421667843418666*g119_1 + 0.10975512601264231*g114_1 + 0.067273952807534246*g173_1 + -0.10964760590711198*g40_1) + (-0.11123337940347686*g161_1 + 0.14098380042954425*g174_1 + 0.54683701526210826*g28_1 + -0.22350312230393624*g34_1 + -0.0032313691236553659*g135_1 + 0.14940317162067368*g134_1 + 0.085041180466403452*g145_1 + -0.19482620121670968*g84_1 + -0.08855498850858351*g191_1 + 0.086368771679039363*g99_1 + 0.090571319703571559*g167_1 + 0.075895313062231101*g157_1);
    moment_arm[0 * kMaxElements + 25] = a0[0]; moment_arm[1 * kMaxElements + 25] = a0[1]; moment_arm[2 * kMaxElements + 25] = a0[2]; moment_arm[3 * kMaxElements + 25] = a1[0]; moment_arm[4 * kMaxElements + 25] = a1[1]; moment_arm[5 * kMaxElements + 25] = a1[2]; L[25] = a0[3] + a1[3]; }
  { const v4d a0 = (0.066908838247963648*e_len + -0.13465942790267485*g8_0 + 0.098253837957608919*g174_0 + -0.024772661332611447*g39_0 + 0.041177634685609046*g50_0 + 0.0020951263398106303*g214_0 + -0.018401702335117679*g59_0 + 0.052827334675159661*g186_0 + -0.019937738968038358*g185_0 + 0.11669716443350213*g145_0 + 0.12783196719393086*g135_0 + 0.10115448004225372*g204_0 + 0.088476912899647375*g157_0 + -0.0048821054669892132*g209_0 + 0.042706598695297998*g196_0 + -0.13776620226052655*g57_0 + -0.17843993988397022*g49_0 + 0.11501508379514355*g190_0) + (-0.12474732186951454*g55_0 + -0.017952646626594009*g138_0 + 0.032661417559618731*g144_0 + 0.02286361900291883*g130_0 + -0.06031188691274627*g210_0 + 0.11470203411576461*g173_0 + -0.16807251264648462*g10_0 + 0.074580915453726471*g134_0 + 0.028575036193840459*g213_0 + 0.029492766360737614*g147_0 + 0.045539282836276555*g170_0 + -0.050234429587102156*g195_0 + 0.13889077515821274*g169_0 + 0.097252485924577234*g175_0 + 0.14027286549226933*g197_0 + -0.021299985995376112*g42_0 + -0.080595958348669727*g161_0 + 0.058070383383080834*g203_0); const v4d a1 = (-0.12474732186951454*g55_1 + 0.098253837957608919*g174_1 + -0.024772661332611447*g39_1 + 0.02286361900291883*g130_1 + 0.11470203411576461*g173_1 + 0.0050076387234016355*g35_1 + 0.074580915453726471*g134_1 + 0.10209336411096273*g34_1 + 0.12783196719393086*g135_1 + 0.098053037610352944*g94_1 + 0.039738378665480002*g33_1 + 0.088476912899647375*g157_1 + -0.0048821054669892132*g209_1 + 0.14027286549226933*g197_1 + 0.11501508379514355*g190_1) + (-0.017952646626594009*g138_1 + 0.032661417559618731*g144_1 + 0.073867532893606244*g7_1 + -0.06031188691274627*g210_1 + -0.21176873430885923*g6_1 + 0.052827334675159661*g186_1 + -0.019937738968038358*g185_1 + 0.11669716443350213*g145_1 + -0.077856561165508195*g5_1 + 0.061947580544028963*g99_1 + -0.050234429587102156*g195_1 + 0.13889077515821274*g169_1 + 0.042706598695297998*g196_1 + -0.080595958348669727*g161_1 + 0.058070383383080834*g203_1);
    moment_arm[0 * kMaxElements + 26] = a0[0]; moment_arm[1 * kMaxElements + 26] = a0[1]; moment_arm[2 * kMaxElements + 26] = a0[2]; moment_arm[3 * kMaxElements + 26] = a1[0]; moment_arm[4 * kMaxElements + 26] = a1[1]; moment_arm[5 * kMaxElements + 26] = a1[2]; L[26] = a0[3] + a1[3]; }
  { const v4d a0 = (0.10437876889133614*e_len + -0.11308803863254925*g8_0 + -0.14748612134995348*g10_0 + 0.09529427451167749*g170_0 + -0.12304473139635423*g49_0 + 0.12571118992497385*g174_0 + -0.1277970734419151*g139_0 + 0.088576422086686618*g196_0 + 0.056045628930929139*g145_0 + 0.12293421106344879*g157_0 + 0.035723515068963034*g198_0 + -0.13209195931699802*g57_0 + -0.024649496890424779*g9_0 + -0.054379597913134771*g191_0) + (-0.050538227562712611*g190_0 + 0.049709306357492752*g185_0 + 0.024032493151935456*g176_0 + 0.1213295325824658*g134_0 + -0.039768484688871307*g42_0 + -0.065142900225368783*g46_0 + 0.039274865027118334*g58_0 + 0.033956917325633586*g172_0 + 0.015005733135630571*g144_0 + 0.015272363717630692*g147_0 + 0.0061965763957229575*g212_0 + 0.16979360932876486*g168_0 + 0.18911593822520106*g197_0 + 0.09406892441662168*g169_0); const v4d a1 = (-0.050538227562712611*g190_1 + 0.15778209164276394*g28_1 + 0.1213295325824658*g134_1 + 0.071304553329902987*g94_1 + 0.24455061936419986*g119_1 + -0.065142900225368783*g46_1 + 0.088576422086686618*g196_1 + 0.033956917325633586*g172_1 + 0.015005733135630571*g144_1 + 0.12293421106344879*g157_1 + 0.0120365595020281*g35_1 + -0.044257460907864324*g5_1 + -0.054379597913134771*g191_1) + (0.049709306357492752*g185_1 + -0.29848014380968557*g34_1 + 0.042991218823824187*g114_1 + 0.020912082265203375*g120_1 + 0.12571118992497385*g174_1 + -0.1277970734419151*g139_1 + -0.050274313713832862*g118_1 + 0.056045628930929139*g145_1 + -0.2778266879529061*g113_1 + 0.064880441450821363*g99_1 + 0.16979360932876486*g168_1 + 0.18911593822520106*g197_1 + 0.09406892441662168*g169_1);
    moment_arm[0 * kMaxElements + 27] = a0[0]; moment_arm[1 * kMaxElements + 27] = a0[1]; moment_arm[2 * kMaxElements + 27] = a0[2]; moment_arm[3 * kMaxElements + 27] = a1[0]; moment_arm[4 * kMaxElements + 27] = a1[1]; moment_arm[5 * kMaxElements + 27] = a1[2]; L[27] = a0[3] + a1[3]; }
  { const v4d a0 = (0.11660500616669828*e_len + -0.16666461939193022*g40_0 + 0.088332791837065647*g170_0 + -0.23617854984209979*g56_0 + 0.12110233129963101*g182_0 + 0.13278955222909267*g213_0 + -0.16261605286145625*g49_0 + 0.097106093357081341*g153_0 + 0.078737185233110643*g157_0 + 0.13755026600172029*g186_0) + (-0.46770345468338675*g190_0 + 0.084901415276379927*g54_0 + -0.1043434200614549*g8_0 + 0.0082084666516363518*g140_0 + 0.39078044989698535*g55_0 + 0.12757007533126652*g174_0 + 0.10885426190762794*g145_0 + 0.13419645041350919*g58_0 + -0.045984795165129856*g211_0); const v4d a1 = (-0.46770345468338675*g190_1 + 0.084901415276379927*g54_1 + 0.0082084666516363518*g140_1 + -0.07110119421981452*g84_1 + 0.12757007533126652*g174_1 + 0.069094589615924129*g94_1 + 0.097106093357081341*g153_1 + -0.045984795165129856*g211_1 + -0.057072429372373806*g33_1) + (-0.16666461939193022*g40_1 + -0.23617854984209979*g56_1 + 0.12110233129963101*g182_1 + 0.39078044989698535*g55_1 + -0.054046086232020944*g34_1 + 0.10885426190762794*g145_1 + 0.078737185233110643*g157_1 + 0.13755026600172029*g186_1);
    moment_arm[0 * kMaxElements + 28] = a0[0]; moment_arm[1 * kMaxElements + 28] = a0[1]; moment_arm[2 * kMaxElements + 28] = a0[2]; moment_arm[3 * kMaxElements + 28] = a1[0]; moment_arm[4 * kMaxElements + 28] = a1[1]; moment_arm[5 * kMaxElements + 28] = a1[2]; L[28] = a0[3] + a1[3]; }
  { const v4d a0 = (0.11514898182039457*e_len + 0.19648096579604873*g185_0 + 0.053642477659145343*g173_0 + -0.023556056366052777*g157_0 + -0.13880996440398066*g211_0 + 0.02529203933601322*g202_0 + 0.091869528793392774*g190_0 + -0.098309342983352727*g9_0 + 0.14085192775341704*g174_0 + -0.14588574501741108*g47_0 + -0.042508288063049467*g201_0 + 0.033250545639075098*g198_0 + 0.10970054468188588*g168_0 + 0.27214648994752455*g54_0) + (-0.17230644910656467*g56_0 + -0.19060831979875456*g49_0 + 0.042139951679586882*g175_0 + 0.098743985399603537*g59_0 + 0.072307101573446206*g169_0 + -0.037983689798869992*g167_0 + -0.011712608429639249*g146_0 + 0.039386871090536929*g197_0 + 0.14951478181376432*g156_0 + 0.044303788426179005*g170_0 + -0.31218501765349038*g189_0 + 0.092157138336234914*g196_0 + -0.014968487965479022*g41_0); const v4d a1 = (-0.17230644910656467*g56_1 + 0.053642477659145343*g173_1 + -0.023556056366052777*g157_1 + 0.072307101573446206*g169_1 + 0.02529203933601322*g202_1 + -0.037983689798869992*g167_1 + -0.011712608429639249*g146_1 + 0.039386871090536929*g197_1 + 0.14085192775341704*g174_1 + -0.14588574501741108*g47_1 + -0.31218501765349038*g189_1 + 0.10970054468188588*g168_1 + -0.16836826451926323*g118_1 + 0.053878969272664896*g28_1) + (0.19648096579604873*g185_1 + 0.021953788896390262*g33_1 + -0.13880996440398066*g211_1 + -0.1322414741093742*g109_1 + -0.062648898552713203*g84_1 + 0.091869528793392774*g190_1 + 0.023632460099932938*g6_1 + -0.012392489162749614*g99_1 + 0.14951478181376432*g156_1 + -0.042508288063049467*g201_1 + 0.092157138336234914*g196_1 + -0.014968487965479022*g41_1 + 0.27214648994752455*g54_1);
    moment_arm[0 * kMaxElements + 29] = a0[0]; moment_arm[1 * kMaxElements + 29] = a0[1]; moment_arm[2 * kMaxElements + 29] = a0[2]; moment_arm[3 * kMaxElements + 29] = a1[0]; moment_arm[4 * kMaxElements + 29] = a1[1]; moment_arm[5 * kMaxElements + 29] = a1[2]; L[29] = a0[3] + a1[3]; }
  { const v4d a0 = (0.055573736952935354*e_len + 0.0369840288805783*g203_0 + 0.078040161881423264*g173_0 + -0.082257158860820814*g9_0 + -0.014314693795077018*g176_0 + -0.096191680807842114*g153_0 + 0.098277216332526687*g50_0 + -0.12970420061384835*g49_0 + 0.06333514715812838*g134_0 + 0.0098318443060299229*g197_0 + 0.12946428023745044*g161_0) + (-0.33079278137335294*g56_0 + 0.021822474397360021*g59_0 + 0.060345013648600884*g175_0 + 0.26471684483878033*g191_0 + -0.1721234083629864*g46_0 + 0.026410308232767642*g205_0 + 0.034523079106624083*g39_0 + 0.02310978056902804*g8_0 + -0.15406322447771553*g162_0 + 0.079388364798719052*g202_0 + 0.013820628045016574*g198_0); const v4d a1 = (-0.33079278137335294*g56_1 + 0.0369840288805783*g203_1 + 0.078040161881423264*g173_1 + -0.1721234083629864*g46_1 + 0.034183161958284768*g34_1 + 0.06333514715812838*g134_1 + 0.0098318443060299229*g197_1 + -0.03846470388589826*g33_1 + 0.028629997498605061*g35_1) + (0.02367320602933198*g109_1 + 0.041304571273650975*g120_1 + 0.26471684483878033*g191_1 + -0.096191680807842114*g153_1 + 0.034523079106624083*g39_1 + -0.15406322447771553*g162_1 + 0.079388364798719052*g202_1 + 0.12946428023745044*g161_1);
    moment_arm[0 * kMaxElements + 30] = a0[0]; moment_arm[1 * kMaxElements + 30] = a0[1]; moment_arm[2 * kMaxElements + 30] = a0[2]; moment_arm[3 * kMaxElements + 30] = a1[0]; moment_arm[4 * kMaxElements + 30] = a1[1]; moment_arm[5 * kMaxElements + 30] = a1[2]; L[30] = a0[3] + a1[3]; }
  { const v4d a0 = (-0.025860284012663205*e_len + -0.12219562980068062*g10_0 + -0.065713660430356646*g49_0 + -0.039514275787011374*g169_0 + 0.018289484953932178*g8_0 + 0.16362414489542879*g157_0 + 0.030670599515148299*g47_0 + 0.008652956879878106*g146_0) + (0.033675347103600276*g56_0 + 0.027277578533824499*g210_0 + 0.090012114828068521*g168_0 + 0.0097774165259502804*g170_0 + -0.16404586862624934*g173_0 + 0.031177350293548414*g59_0 + 0.016053207488558846*g204_0); const v4d a1 = (0.033675347103600276*g56_1 + -0.0036513194299225751*g120_1 + 0.090012114828068521*g168_1 + -0.16404586862624934*g173_1 + -0.028421888350456961*g118_1 + 0.058860696395138357*g28_1 + 0.008652956879878106*g146_1) + (-0.079490204277563439*g113_1 + 0.027277578533824499*g210_1 + -0.039514275787011374*g169_1 + 0.16362414489542879*g157_1 + 0.10554990158565104*g7_1 + 0.030670599515148299*g47_1);
    moment_arm[0 * kMaxElements + 31] = a0[0]; moment_arm[1 * kMaxElements + 31] = a0[1]; moment_arm[2 * kMaxElements + 31] = a0[2]; moment_arm[3 * kMaxElements + 31] = a1[0]; moment_arm[4 * kMaxElements + 31] = a1[1]; moment_arm[5 * kMaxElements + 31] = a1[2]; L[31] = a0[3] + a1[3]; }
  { const v4d a0 = (0.01472424243307798*e_len + -0.16850715061115137*g58_0 + 0.0089376281879034944*g204_0 + 0.15950030125817236*g203_0 + 0.0046986474707073839*g55_0 + -0.097630949173753492*g173_0 + 0.1897030262486723*g157_0 + -0.030779955674043701*g210_0 + -0.2176341096058276*g56_0 + -0.071645833534722203*g213_0 + -0.1056906355058199*g202_0 + 0.022337082600761747*g48_0) + (0.067207724129106736*g190_0 + 0.11816856393807881*g186_0 + 0.16398342803202287*g191_0 + -0.042591834914933083*g57_0 + -0.071667832721788685*g135_0 + 0.053757924025603337*g41_0 + 0.022932658014604035*g59_0 + -0.026871347879362937*g168_0 + 0.011997374783009097*g42_0 + -0.14957347655180725*g49_0 + -0.049340392397863871*g140_0 + 0.045818757485296395*g50_0); const v4d a1 = (0.067207724129106736*g190_1 + 0.16398342803202287*g191_1 + 0.067360890729950565*g120_1 + 0.0046986474707073839*g55_1 + -0.097630949173753492*g173_1 + 0.053757924025603337*g41_1 + -0.030779955674043701*g210_1 + -0.2176341096058276*g56_1 + -0.049340392397863871*g140_1) + (0.11816856393807881*g186_1 + 0.15950030125817236*g203_1 + 0.023632474606622808*g118_1 + -0.071667832721788685*g135_1 + -0.082836064459941142*g99_1 + 0.1897030262486723*g157_1 + -0.026871347879362937*g168_1 + -0.1056906355058199*g202_1 + 0.022337082600761747*g48_1);
    moment_arm[0 * kMaxElements + 32] = a0[0]; moment_arm[1 * kMaxElements + 32] = a0[1]; moment_arm[2 * kMaxElements + 32] = a0[2]; moment_arm[3 * kMaxElements + 32] = a1[0]; moment_arm[4 * kMaxElements + 32] = a1[1]; moment_arm[5 * kMaxElements + 32] = a1[2]; L[32] = a0[3] + a1[3]; }
  { const v4d a0 = (0.042141727898770992*e_len + 0.085203880256780676*g9_0 + -0.15701109226958232*g209_0 + -0.034717934194574113*g55_0 + -0.13235319414876703*g173_0 + -0.052708150096745891*g203_0 + -0.056855839028839179*g135_0 + 0.017833185482956263*g54_0 + -0.10599407491597969*g201_0 + 0.019831903926909825*g175_0 + -0.035195855567442716*g144_0 + 0.062070576039723706*g153_0 + 0.13952139674441327*g174_0 + -0.07410990070298587*g213_0 + -0.056769373269451938*g50_0 + -0.067544334795321098*g162_0) + (0.049835105649014715*g190_0 + 0.20807463372466037*g185_0 + -0.20032195728068436*g169_0 + 0.098797987277003729*g191_0 + 0.034250214504330419*g197_0 + -0.0013402211653590844*g204_0 + 0.10153626968995169*g157_0 + -0.006585349247932467*g147_0 + 0.045921397869944362*g146_0 + 0.04527225901610387*g139_0 + -0.10020141322099044*g57_0 + -0.079864064294810203*g48_0 + -0.16784185865193776*g56_0 + 0.086277462559682286*g167_0 + 0.02702030815952489*g198_0); const v4d a1 = (0.049835105649014715*g190_1 + -0.15701109226958232*g209_1 + -0.070521210767589701*g7_1 + -0.045969335659989848*g98_1 + -0.036684558769620006*g119_1 + -0.13235319414876703*g173_1 + -0.052708150096745891*g203_1 + 0.10153626968995169*g157_1 + -0.10599407491597969*g201_1 + 0.04527225901610387*g139_1 + 0.088856718258355533*g120_1 + -0.079864064294810203*g48_1 + -0.076602184677922278*g99_1 + 0.086277462559682286*g167_1) + (0.20807463372466037*g185_1 + -0.20032195728068436*g169_1 + -0.034717934194574113*g55_1 + 0.098797987277003729*g191_1 + 0.027497338029268771*g5_1 + 0.034250214504330419*g197_1 + -0.056855839028839179*g135_1 + 0.017833185482956263*g54_1 + 0.045921397869944362*g146_1 + -0.035195855567442716*g144_1 + 0.062070576039723706*g153_1 + 0.13952139674441327*g174_1 + -0.16784185865193776*g56_1 + -0.067544334795321098*g162_1);
    moment_arm[0 * kMaxElements + 33] = a0[0]; moment_arm[1 * kMaxElements + 33] = a0[1]; moment_arm[2 * kMaxElements + 33] = a0[2]; moment_arm[3 * kMaxElements + 33] = a1[0]; moment_arm[4 * kMaxElements + 33] = a1[1]; moment_arm[5 * kMaxElements + 33] = a1[2]; L[33] = a0[3] + a1[3]; }
  { const v4d a0 = (0.0011276004039514392*e_len + 0.11904361219144796*g9_0 + 0.079009598181577739*g203_0 + 0.10905644749112363*g197_0 + -0.085054610216042104*g173_0 + -0.041361843835557605*g139_0 + -0.064613558791063272*g163_0 + 0.019262154963923091*g175_0 + 0.091390456357530681*g191_0 + -0.2069653418901431*g56_0 + 0.03568193935644251*g214_0 + 0.028122798859868164*g189_0 + 0.026334882289110174*g174_0) + (-0.14542353594613133*g190_0 + -0.042467202972617538*g169_0 + -0.1560681170659588*g57_0 + 0.038048695516711056*g10_0 + 0.12951478487563003*g211_0 + 0.060818643295327456*g157_0 + 0.061298921756114184*g204_0 + 0.030566792395520334*g41_0 + -0.055853801556674118*g8_0 + 0.024453259657897328*g140_0 + 0.016350016618892935*g46_0 + -0.052692772601396994*g49_0 + -0.033323110682637623*g135_0); const v4d a1 = (-0.14542353594613133*g190_1 + -0.042467202972617538*g169_1 + 0.047459860364347357*g119_1 + 0.14000121895338091*g94_1 + -0.089242994460417183*g98_1 + 0.12951478487563003*g211_1 + 0.060818643295327456*g157_1 + -0.093870479317491401*g6_1 + 0.030566792395520334*g41_1 + 0.091390456357530681*g191_1 + 0.024453259657897328*g140_1 + 0.028122798859868164*g189_1 + -0.033323110682637623*g135_1) + (0.075489744983804966*g24_1 + 0.079009598181577739*g203_1 + 0.10905644749112363*g197_1 + -0.028086879580745166*g113_1 + -0.085054610216042104*g173_1 + -0.041361843835557605*g139_1 + -0.064613558791063272*g163_1 + 0.047302956279440256*g120_1 + 0.057220987039875548*g5_1 + -0.2069653418901431*g56_1 + 0.016350016618892935*g46_1 + 0.026334882289110174*g174_1);
    moment_arm[0 * kMaxElements + 34] = a0[0]; moment_arm[1 * kMaxElements + 34] = a0[1]; moment_arm[2 * kMaxElements + 34] = a0[2]; moment_arm[3 * kMaxElements + 34] = a1[0]; moment_arm[4 * kMaxElements + 34] = a1[1]; moment_arm[5 * kMaxElements + 34] = a1[2]; L[34] = a0[3] + a1[3]; }
  { const v4d a0 = (0.023329587719575648*e_len + 0.13564178037981955*g10_0 + 0.0011362829863205612*g49_0 + -0.099650497024486862*g169_0 + 0.067562758265724512*g191_0 + -0.0069332458231120952*g146_0 + 0.0085430439912388793*g205_0 + -0.017664425179734135*g210_0 + 0.037454340762621982*g54_0 + -0.21328045195002804*g48_0 + -0.12286654496932226*g57_0 + 0.022707491886521432*g140_0 + 0.048949769574520782*g203_0) + (-0.05764219245324767*g162_0 + 0.1850725542988346*g9_0 + -0.066519888871521327*g212_0 + 0.10944289310814249*g163_0 + -0.27923636191696283*g56_0 + 0.0328158446051416*g174_0 + -0.14523561308979904*g190_0 + -0.041629386036745666*g213_0 + -0.043576305804890955*g201_0 + -0.037718982166679051*g8_0 + 0.089173156847673754*g59_0 + -0.062556797798151542*g173_0); const v4d a1 = (-0.05764219245324767*g162_1 + -0.055411477931480047*g114_1 + 0.10944289310814249*g163_1 + 0.067562758265724512*g191_1 + -0.0069332458231120952*g146_1 + -0.14523561308979904*g190_1 + 0.037454340762621982*g54_1 + -0.21328045195002804*g48_1 + -0.18307919388222171*g118_1 + -0.062556797798151542*g173_1 + 0.22127017611130192*g33_1) + (-0.0062356716794354098*g5_1 + -0.099650497024486862*g169_1 + -0.070128024546560905*g6_1 + -0.27923636191696283*g56_1 + 0.0328158446051416*g174_1 + -0.017664425179734135*g210_1 + -0.043576305804890955*g201_1 + 0.050846254335257711*g29_1 + 0.022707491886521432*g140_1 + 0.048949769574520782*g203_1);
    moment_arm[0 * kMaxElements + 35] = a0[0]; moment_arm[1 * kMaxElements + 35] = a0[1]; moment_arm[2 * kMaxElements + 35] = a0[2]; moment_arm[3 * kMaxElements + 35] = a1[0]; moment_arm[4 * kMaxElements + 35] = a1[1]; moment_arm[5 * kMaxElements + 35] = a1[2]; L[35] = a0[3] + a1[3]; }
  { const v4d a2 = (0.17458338744227*e_len + -0.10770318217503758*g262_2 + 0.30986650239129165*g17_2 + 0.074989927604106207*g276_2 + -0.0016886970607243729*g16_2 + 0.017291986853230915*g4_2 + 0.0025173069488126404*g285_2 + 0.053284751439595948*g232_2 + 0.05882344749412808*g296_2 + -0.69536966099462127*g69_2 + -0.012366187158333418*g282_2 + -0.010532823152192838*g20_2 + -0.10875886120539222*g257_2) + (-0.013612631431100036*g19_2 + -0.018308499526657113*g3_2 + 0.04072768405181932*g234_2 + -0.0012061220994630767*g252_2 + -0.0051802638780183438*g230_2 + 0.0057634870971738587*g2_2 + -0.0046275337500204334*g18_2 + 0.035020294885006784*g229_2 + 0.0018192178169480953*g74_2 + -0.37583306142076545*g248_2 + 0.049126848994484447*g287_2 + 0.73144530186182344*g225_2);
    moment_arm[6 * kMaxElements + 36] = a2[0]; moment_arm[7 * kMaxElements + 36] = a2[1]; moment_arm[8 * kMaxElements + 36] = a2[2]; L[36] = a2[3]; }
  { const v4d a2 = (0.14977063902917556*e_len + 0.0025092674430518581*g224_2 + 0.038071672154741061*g3_2 + -0.00079714554338302214*g296_2 + -0.016821034861036102*g234_2 + -0.0015556782315748782*g233_2 + -0.00073470234985961507*g276_2 + 0.00076375711346353653*g263_2 + -0.15026379700276674*g253_2 + -0.0086270115467853726*g68_2 + -0.063286448726782726*g17_2 + -0.090207729107077472*g72_2) + (0.0097907654303614738*g16_2 + 0.00027691826003346895*g15_2 + 0.078416348311386164*g69_2 + 0.045027365058783665*g19_2 + 0.040296713351983419*g282_2 + 0.0041566595294290293*g291_2 + -0.0032413536419605674*g231_2 + -0.003348748102188956*g230_2 + 0.014827419851013801*g248_2 + -0.054874902640006905*g225_2 + 0.18206972988438325*g229_2);
    moment_arm[6 * kMaxElements + 37] = a2[0]; moment_arm[7 * kMaxElements + 37] = a2[1]; moment_arm[8 * kMaxElements + 37] = a2[2]; L[37] = a2[3]; }
  { const v4d a2 = (0.13192438426423025*e_len + -0.0041048812485313078*g253_2 + -0.033753105745104935*g74_2 + 0.0018138425175372971*g282_2 + -0.0025272549031412272*g295_2 + 0.082940597815362851*g232_2 + -0.0072079267334362682*g73_2 + -0.14936102274800142*g225_2 + -0.10105077757771683*g17_2 + -0.013154536251366422*g276_2 + 0.009217540895958231*g259_2 + 0.00059959634661664379*g246_2 + -0.0021255291076738873*g252_2) + (0.022754115875854533*g19_2 + 0.15908187042053723*g69_2 + 0.0044946757748070415*g2_2 + 0.033203314291096214*g3_2 + 0.021110696045289732*g287_2 + 0.007922577276563432*g4_2 + 0.005402135368434275*g233_2 + -0.075604789260933808*g257_2 + 0.070593269285594659*g248_2 + 0.00097534919981017527*g281_2 + -0.0055655975235085172*g290_2 + -0.001233391653066901*g254_2);
    moment_arm[6 * kMaxElements + 38] = a2[0]; moment_arm[7 * kMaxElements + 38] = a2[1]; moment_arm[8 * kMaxElements + 38] = a2[2]; L[38] = a2[3]; }
  { const v4d a2 = (0.11101766958416805*e_len + -0.0015444816232241254*g225_2 + 0.023717615046758428*g19_2 + 0.00072223213249632495*g248_2 + -0.0048065477404160631*g17_2 + -0.0050024800273427029*g253_2 + 0.00059231747191871382*g293_2 + 0.0044402349959757441*g260_2) + (0.0079798218547649704*g4_2 + 0.0049954126316480918*g2_2 + -0.0026895084554777733*g232_2 + 0.0020810155040443647*g282_2 + -0.0024813034542557721*g73_2 + -0.0027947660290665198*g291_2 + -0.0034119109417057097*g20_2);
    moment_arm[6 * kMaxElements + 39] = a2[0]; moment_arm[7 * kMaxElements + 39] = a2[1]; moment_arm[8 * kMaxElements + 39] = a2[2]; L[39] = a2[3]; }
  { const v4d a2 = (0.10420296604274459*e_len + -0.053496466999387537*g17_2 + 0.084427442970077926*g72_2 + -0.13810719181168299*g229_2 + 0.061687585915056582*g69_2 + 0.00050682182754140136*g246_2 + 1.3352209959766194e-05*g263_2 + 0.0023521840781238904*g276_2 + 0.0001808240755507824*g15_2) + (0.0068963691088105459*g4_2 + 0.0042547701878738273*g2_2 + -0.028708876622310094*g225_2 + -0.00090406134949582904*g291_2 + 0.09042258168721086*g253_2 + -0.0010676958874276618*g256_2 + -0.021080516416349455*g282_2 + 0.00099211928555448378*g16_2);
    moment_arm[6 * kMaxElements + 40] = a2[0]; moment_arm[7 * kMaxElements + 40] = a2[1]; moment_arm[8 * kMaxElements + 40] = a2[2]; L[40] = a2[3]; }
  { const v4d a2 = (0.14153943030040897*e_len + 0.0013677773888225047*g225_2 + 0.0038865528706406843*g2_2 + 0.025165081011776072*g19_2 + -0.0014089090961480694*g259_2 + -5.1994430662788848e-05*g287_2) + (0.0041818195482766982*g4_2 + -0.0004549438480564936*g282_2 + -0.015017232720615944*g17_2 + -0.003934697994660178*g232_2 + 0.00099599475563756862*g67_2 + -0.00048513638730103402*g293_2);
    moment_arm[6 * kMaxElements + 41] = a2[0]; moment_arm[7 * kMaxElements + 41] = a2[1]; moment_arm[8 * kMaxElements + 41] = a2[2]; L[41] = a2[3]; }
  { const v4d a2 = (0.15693316272310842*e_len + 0.054196103840772149*g225_2 + -0.017392143201165972*g282_2 + -0.13887880540247863*g229_2 + -0.041220397539007185*g248_2 + -0.015092390859811787*g69_2 + -0.0025522174327634053*g234_2 + -0.0012246071353557016*g73_2) + (-0.00015043628221487774*g75_2 + 0.006626877602879909*g4_2 + 0.010069344695396755*g276_2 + 0.0037241233464960478*g2_2 + 0.080888397117878291*g253_2 + 0.097219097540197141*g72_2 + -0.023075011224640576*g17_2);
    moment_arm[6 * kMaxElements + 42] = a2[0]; moment_arm[7 * kMaxElements + 42] = a2[1]; moment_arm[8 * kMaxElements + 42] = a2[2]; L[42] = a2[3]; }
  { const v4d a2 = (0.13963500623628891*e_len + 0.024061675911017433*g19_2 + 0.0027766936358522704*g2_2 + -0.0011142014688907509*g260_2 + 0.0010374474981920407*g223_2) + (-0.01154774684301673*g17_2 + -0.013291034964295395*g3_2 + -0.0048626277954243171*g72_2 + 0.0032929541424644979*g4_2 + 0.0023193665322437519*g69_2);
    moment_arm[6 * kMaxElements + 43] = a2[0]; moment_arm[7 * kMaxElements + 43] = a2[1]; moment_arm[8 * kMaxElements + 43] = a2[2]; L[43] = a2[3]; }
  { const v4d a2 = (0.1480844352799803*e_len + 0.021013194988813329*g19_2 + 0.0028596664247313628*g2_2 + 0.0038537461137463924*g4_2 + 0.001477547210689044*g16_2) + (-0.016737344613379956*g3_2 + -0.005372223539685546*g72_2 + -0.01046217280274243*g17_2 + 0.0028953647238998542*g69_2 + -0.00039116910153477096*g291_2);
    moment_arm[6 * kMaxElements + 44] = a2[0]; moment_arm[7 * kMaxElements + 44] = a2[1]; moment_arm[8 * kMaxElements + 44] = a2[2]; L[44] = a2[3]; }
  { const v4d a2 = (0.13813706300660211*e_len + 0.015873581802469023*g19_2 + -0.004507105212920387*g72_2 + -0.0015870777321478095*g17_2 + -0.00085330295081603919*g235_2) + (-0.026419180701597378*g3_2 + 0.0034226841450876746*g2_2 + 0.0041364217654450983*g20_2 + 0.0015148379016445162*g67_2);
    moment_arm[6 * kMaxElements + 45] = a2[0]; moment_arm[7 * kMaxElements + 45] = a2[1]; moment_arm[8 * kMaxElements + 45] = a2[2]; L[45] = a2[3]; }
  { const v4d a2 = (0.13020914873535078*e_len + 0.0040246205376601209*g234_2 + -0.0023224428145920753*g294_2 + 0.0022702477783133942*g67_2) + (-0.030320685444223994*g3_2 + 0.0032864663206051406*g2_2 + -0.00053538997116235598*g69_2 + 0.0041836952285397577*g74_2);
    moment_arm[6 * kMaxElements + 46] = a2[0]; moment_arm[7 * kMaxElements + 46] = a2[1]; moment_arm[8 * kMaxElements + 46] = a2[2]; L[46] = a2[3]; }
  { const v4d a1 = (0.13937944411691178*e_len + 0.025105202319867008*g102_1 + -0.047544584128926523*g99_1 + -0.019398182065978528*g93_1 + 0.091326459696876083*g84_1 + -0.013388426707772103*g108_1 + -0.0026242263082477718*g88_1 + 0.02578318796201674*g25_1 + -0.10822894099244432*g31_1 + 0.0054612643363878485*g7_1 + -0.0070744626621049161*g86_1 + -0.013836257099931259*g106_1 + -0.036393147088563282*g34_1 + 0.015747689948761998*g22_1) + (0.11014530008765835*g24_1 + -0.0048030648697265314*g27_1 + 0.028740967921374316*g96_1 + -0.026129565057302188*g82_1 + 0.020588644513523185*g116_1 + -0.0054514635838427321*g120_1 + 0.0021891265780643429*g101_1 + -0.01051830996124577*g91_1 + -0.027402329579323658*g33_1 + 0.010879844192999859*g89_1 + 0.023746165783928706*g95_1 + -0.099168967593350185*g29_1 + -0.014439972033851299*g80_1 + 0.0053458092867193175*g105_1); const v4d a2 = (0.025105202319867008*g102_2 + -0.054250611976089762*g17_2 + 0.028740967921374316*g96_2 + -0.012009131817053155*g4_2 + -0.026129565057302188*g82_2 + 0.020588644513523185*g116_2 + -0.0026242263082477718*g88_2 + 0.02578318796201674*g25_2 + -0.01051830996124577*g91_2 + 0.0012024245016873218*g70_2 + 0.010879844192999859*g89_2 + 0.00044217462580346069*g75_2 + 0.023746165783928706*g95_2 + 0.0020098858833849549*g67_2 + 0.015747689948761998*g22_2 + -0.010692396171112712*g19_2) + (-0.0048030648697265314*g27_2 + -0.0103539226725653*g74_2 + -0.019398182065978528*g93_2 + 0.0063364151996237955*g69_2 + 0.095862074807236575*g3_2 + -0.013388426707772103*g108_2 + 0.0021891265780643429*g101_2 + -0.0041893390018733993*g18_2 + -0.10822894099244432*g31_2 + 0.0017054550871081105*g73_2 + 0.0082945600643434311*g72_2 + -0.0070744626621049161*g86_2 + -0.013836257099931259*g106_2 + -0.014439972033851299*g80_2 + 0.0053458092867193175*g105_2);
    moment_arm[3 * kMaxElements + 47] = a1[0]; moment_arm[4 * kMaxElements + 47] = a1[1]; moment_arm[5 * kMaxElements + 47] = a1[2]; moment_arm[6 * kMaxElements + 47] = a2[0]; moment_arm[7 * kMaxElements + 47] = a2[1]; moment_arm[8 * kMaxElements + 47] = a2[2]; L[47] = a1[3] + a2[3]; }
  { const v4d a1 = (0.16984270094976286*e_len + -0.085105074279649556*g5_1 + -0.23502450939283065*g98_1 + -0.0071622575798614219*g116_1 + -0.27823535985637315*g28_1 + -0.0043827716794029685*g108_1 + -0.0027508892659398542*g96_1 + -0.0055614324464986114*g95_1 + 0.0034076032925671757*g100_1 + 0.0027682308928808574*g120_1 + -0.055779476632021881*g31_1 + -0.01395160819319999*g80_1) + (0.0037731148037981042*g112_1 + 0.014422471626641032*g107_1 + 0.028823860539130164*g92_1 + 0.033052544765166739*g109_1 + 0.013799560758567744*g78_1 + -0.018427917994916398*g82_1 + -0.012935256883347884*g87_1 + -0.0082145111180601492*g106_1 + 0.012719228291730285*g102_1 + 0.079849418890459017*g99_1 + 0.1170429249101796*g113_1 + 0.0094543538654000506*g89_1); const v4d a2 = (0.0037731148037981042*g112_2 + -0.0046210234265750428*g4_2 + -0.0071622575798614219*g116_2 + 0.079530993279952125*g3_2 + -0.034498350088437275*g17_2 + -0.018427917994916398*g82_2 + 0.0093399905360294494*g72_2 + -0.012935256883347884*g87_2 + -0.0082145111180601492*g106_2 + 0.0026306076576088216*g68_2 + 0.012719228291730285*g102_2 + -0.01395160819319999*g80_2) + (0.014422471626641032*g107_2 + 0.028823860539130164*g92_2 + 0.013799560758567744*g78_2 + -0.0097477048165998757*g74_2 + -0.0043827716794029685*g108_2 + -0.023810362925206718*g19_2 + -0.0027508892659398542*g96_2 + -0.0055614324464986114*g95_2 + -0.0059117720935135997*g2_2 + 0.0034076032925671757*g100_2 + -0.055779476632021881*g31_2 + 0.0094543538654000506*g89_2);
    moment_arm[3 * kMaxElements + 48] = a1[0]; moment_arm[4 * kMaxElements + 48] = a1[1]; moment_arm[5 * kMaxElements + 48] = a1[2]; moment_arm[6 * kMaxElements + 48] = a2[0]; moment_arm[7 * kMaxElements + 48] = a2[1]; moment_arm[8 * kMaxElements + 48] = a2[2]; L[48] = a1[3] + a2[3]; }
  { const v4d a1 = (0.15576230880248026*e_len + 0.014744503130220151*g119_1 + 0.014981005158921552*g102_1 + -0.021995663973803495*g99_1 + 0.023723866801528395*g27_1 + -0.059039104250469619*g33_1 + -0.0030628305626507263*g22_1 + -0.0061377006444628505*g77_1 + -0.014895403773614774*g110_1 + 0.021974812988325224*g95_1 + 0.019455432174951316*g97_1 + 0.015305154718070944*g78_1 + -0.0054533063647430064*g118_1 + -0.099459414927203463*g29_1) + (-0.0037669934437862852*g24_1 + -0.068068076138575573*g31_1 + -0.0015703206836296655*g116_1 + 0.001835929438890625*g108_1 + 0.002532471319692405*g82_1 + -0.033952461590703864*g92_1 + 0.033578154726706208*g25_1 + -0.017983731909360649*g80_1 + 0.040246035219528041*g114_1 + 0.0044451389064344704*g105_1 + -0.0036636913899296695*g86_1 + 0.047429664132813854*g28_1 + 0.0017389494842589173*g107_1 + -0.029045497879416151*g26_1); const v4d a2 = (-0.027063850816851205*g19_2 + 0.014981005158921552*g102_2 + -0.00087791112860847239*g20_2 + 0.001835929438890625*g108_2 + -0.028146333962972486*g17_2 + -0.033952461590703864*g92_2 + -0.0030628305626507263*g22_2 + -0.0061377006444628505*g77_2 + -0.017983731909360649*g80_2 + 0.021974812988325224*g95_2 + 0.0044451389064344704*g105_2 + -0.0036636913899296695*g86_2 + 0.0017389494842589173*g107_2) + (-0.068068076138575573*g31_2 + -0.0015703206836296655*g116_2 + 0.066800789643819053*g3_2 + 0.023723866801528395*g27_2 + 0.002532471319692405*g82_2 + 0.0098058238480431704*g72_2 + 0.033578154726706208*g25_2 + -0.0097574139661586751*g74_2 + -0.014895403773614774*g110_2 + 0.0026204918966480383*g67_2 + 0.019455432174951316*g97_2 + 0.015305154718070944*g78_2 + -0.029045497879416151*g26_2);
    moment_arm[3 * kMaxElements + 49] = a1[0]; moment_arm[4 * kMaxElements + 49] = a1[1]; moment_arm[5 * kMaxElements + 49] = a1[2]; moment_arm[6 * kMaxElements + 49] = a2[0]; moment_arm[7 * kMaxElements + 49] = a2[1]; moment_arm[8 * kMaxElements + 49] = a2[2]; L[49] = a1[3] + a2[3]; }
  { const v4d a1 = (0.16333470490877566*e_len + 0.02407746867094171*g27_1 + 0.0061471630016699183*g102_1 + -0.0031911713199400775*g104_1 + 0.011321174642683375*g7_1 + 0.023846190590523366*g84_1 + -0.014216967870317225*g96_1 + 0.0029461059414265293*g115_1 + 0.069460139944857155*g109_1 + -0.011635862986534493*g87_1 + -0.0055988966326298521*g77_1 + -0.041380605246335626*g5_1 + 0.0030795600523233378*g25_1 + -0.014102491976502356*g26_1 + 0.0012626477270094179*g103_1 + 0.0049591189807613109*g90_1) + (-0.0049808280696813636*g24_1 + -0.077067481077385036*g29_1 + 0.099800059505910241*g114_1 + -0.026002994088192538*g112_1 + -0.015491753650197542*g82_1 + -0.011197883844047029*g80_1 + 0.012353381153386802*g97_1 + 0.01541147292475898*g78_1 + -0.058130753968690219*g31_1 + 0.046240704260531333*g34_1 + 0.007284037122312851*g89_1 + -0.0027451661507447832*g81_1 + -0.0093265189897700374*g32_1 + 0.0025655045021048036*g100_1 + 0.0045098810310243336*g105_1); const v4d a2 = (0.02407746867094171*g27_2 + 0.071209628301152045*g3_2 + -0.026002994088192538*g112_2 + -0.015491753650197542*g82_2 + -0.014216967870317225*g96_2 + -0.0060822826824579509*g2_2 + 0.01541147292475898*g78_2 + -0.058130753968690219*g31_2 + -0.029206789243601136*g17_2 + 0.0089726717963943981*g72_2 + 0.007284037122312851*g89_2 + -0.0027451661507447832*g81_2 + -0.0093265189897700374*g32_2 + 0.0012605035656409246*g69_2 + 0.0012626477270094179*g103_2 + 0.0049591189807613109*g90_2) + (0.0061471630016699183*g102_2 + -0.0031911713199400775*g104_2 + -0.0099870229196963468*g74_2 + -0.011197883844047029*g80_2 + 0.012353381153386802*g97_2 + 0.0029461059414265293*g115_2 + 0.0014430286187216473*g68_2 + -0.021193258738965506*g19_2 + -0.011635862986534493*g87_2 + -0.0055988966326298521*g77_2 + 0.00049833850505582201*g66_2 + 0.0030795600523233378*g25_2 + -0.014102491976502356*g26_2 + 0.0025655045021048036*g100_2 + 0.0045098810310243336*g105_2);
    moment_arm[3 * kMaxElements + 50] = a1[0]; moment_arm[4 * kMaxElements + 50] = a1[1]; moment_arm[5 * kMaxElements + 50] = a1[2]; moment_arm[6 * kMaxElements + 50] = a2[0]; moment_arm[7 * kMaxElements + 50] = a2[1]; moment_arm[8 * kMaxElements + 50] = a2[2]; L[50] = a1[3] + a2[3]; }
  { const v4d a2 = (0.16319374818907079*e_len + -0.00017254294702921696*g69_2 + 0.0082406321532403418*g3_2 + 0.00034428792305349083*g297_2 + -0.0037814638788647458*g74_2 + -0.0064341225058615588*g17_2) + (-0.026914516474557674*g19_2 + 0.00037416349260522603*g282_2 + 0.00079540932734571863*g15_2 + 0.0015410006487466858*g18_2 + 0.002677160664029401*g234_2 + 0.0018952183285911438*g229_2);
    moment_arm[6 * kMaxElements + 51] = a2[0]; moment_arm[7 * kMaxElements + 51] = a2[1]; moment_arm[8 * kMaxElements + 51] = a2[2]; L[51] = a2[3]; }
  { const v4d a2 = (0.17745423565073179*e_len + 0.013246650292477296*g3_2 + 0.0058991743602023819*g72_2 + -0.0042766155498672551*g74_2 + 0.00077394117939191375*g287_2) + (-0.031176418399920237*g19_2 + -0.0060659207789059708*g17_2 + 0.0018427896308484432*g16_2 + 0.0012799524761196752*g75_2);
    moment_arm[6 * kMaxElements + 52] = a2[0]; moment_arm[7 * kMaxElements + 52] = a2[1]; moment_arm[8 * kMaxElements + 52] = a2[2]; L[52] = a2[3]; }
  { const v4d a2 = (0.19250796026841702*e_len + 0.00042283769950382321*g248_2 + 0.006849020962998731*g16_2 + 0.00043437946889936631*g297_2 + 0.0058699783553835322*g3_2 + 0.0040136474142516568*g253_2 + -0.00053617258456930498*g73_2 + 0.00061571672288320261*g4_2 + -0.0022466283710769566*g232_2) + (-0.032810678145436929*g19_2 + -0.0010222331477005894*g282_2 + -0.011842611312648813*g68_2 + -0.00075001116997755533*g275_2 + -0.0042761004804720212*g69_2 + 0.0010775963582855298*g18_2 + 0.0069636777962814042*g224_2 + 0.0011792282847673354*g294_2);
    moment_arm[6 * kMaxElements + 53] = a2[0]; moment_arm[7 * kMaxElements + 53] = a2[1]; moment_arm[8 * kMaxElements + 53] = a2[2]; L[53] = a2[3]; }
  { const v4d a2 = (0.087869980944185369*e_len + 0.014643780311148375*g4_2 + 0.003401044758462556*g257_2 + -0.0034394184283632924*g228_2 + -0.0074549247935674252*g15_2 + 0.0011395467567401555*g251_2 + -0.0023033659687782247*g227_2 + -0.0054866482259867781*g20_2 + 0.0015910795801112273*g226_2 + -0.010728814695207872*g293_2 + 0.0026267086160523378*g233_2 + -0.0030896451560659833*g288_2 + 0.011811163037600231*g69_2 + 0.001657364783182233*g66_2 + -0.0024107415751879152*g294_2) + (-0.015045319120065433*g17_2 + 0.01503235236644344*g2_2 + -0.0047305486616303818*g19_2 + 0.0022074995931857652*g286_2 + -0.008326104230914835*g225_2 + -0.015057373243495886*g18_2 + 0.0038699350628732996*g73_2 + 0.0014017431853493233*g74_2 + -0.00098515929778973253*g224_2 + 0.013036189743163708*g259_2 + 0.0085290728077761589*g70_2 + 0.00075072079704669077*g246_2 + 0.0022308727426337059*g248_2 + 0.00014664138562204781*g297_2 + 0.0049744770164780209*g234_2);
    moment_arm[6 * kMaxElements + 54] = a2[0]; moment_arm[7 * kMaxElements + 54] = a2[1]; moment_arm[8 * kMaxElements + 54] = a2[2]; L[54] = a2[3]; }
  { const v4d a2 = (0.17356621612999892*e_len + 0.0069679171336001168*g74_2 + 0.00024494054812902678*g69_2 + -0.0060161974996631746*g19_2 + -0.0055558098165239735*g18_2 + -0.00015339387219721797*g230_2 + 0.00049330848389187473*g225_2 + 0.0040093765235933035*g231_2 + 0.0012273666634509152*g66_2 + 0.0029747427038394349*g70_2 + -0.0034551823471286802*g294_2 + 0.0040975032207306904*g260_2) + (-0.0089510384405577393*g17_2 + 0.011095552258008522*g2_2 + 0.010534497562897094*g4_2 + 0.00073486892350355657*g287_2 + -0.0037437352867697518*g15_2 + 0.0010315201930348888*g75_2 + -0.00059606750620098351*g68_2 + -0.0049801106251140198*g3_2 + -0.0020491538512592291*g228_2 + 0.00054129728991675981*g280_2 + -0.0036889695994661463*g20_2);
    moment_arm[6 * kMaxElements + 55] = a2[0]; moment_arm[7 * kMaxElements + 55] = a2[1]; moment_arm[8 * kMaxElements + 55] = a2[2]; L[55] = a2[3]; }
  { const v4d a2 = (0.14838254604080264*e_len + 0.010949119986949701*g74_2 + -0.010288938489065579*g17_2 + -0.0077535390780109782*g19_2 + -0.0097260418265631473*g18_2 + 0.0045063713564514598*g255_2 + 0.0055265558271342559*g73_2 + -0.0039599355335162723*g15_2 + 0.0018892639919294116*g69_2 + -0.0069315710061313802*g20_2 + 0.0082001858345322146*g70_2 + 0.0010581670720069755*g222_2) + (-0.0053066784121569279*g3_2 + 0.012015745383368479*g2_2 + 0.012032792953201712*g4_2 + 0.00092905729632579903*g287_2 + 0.0001029954243784302*g223_2 + -0.00010331132460065307*g72_2 + 0.0027665820486616061*g75_2 + -0.0010270174925429774*g68_2 + 0.00024142907899367958*g226_2 + -0.0015037010045402587*g296_2 + -0.0059377847249093884*g230_2 + -0.0033777944487118124*g227_2);
    moment_arm[6 * kMaxElements + 56] = a2[0]; moment_arm[7 * kMaxElements + 56] = a2[1]; moment_arm[8 * kMaxElements + 56] = a2[2]; L[56] = a2[3]; }
  { const v4d a2 = (0.13999229537492067*e_len + -0.0029830961808690591*g74_2 + 0.0082804691484007382*g4_2 + -0.0045920405800400042*g228_2 + -0.0091616812387527204*g17_2 + -0.0025592899130964758*g15_2 + -0.0045612834519968759*g18_2 + -0.00038231210222328951*g247_2 + 0.0069313380187213417*g232_2 + 0.0040434519696275267*g234_2 + 0.0071709396414395615*g260_2) + (-0.012571568159364178*g3_2 + 0.010529600748332412*g2_2 + -0.004356895770962127*g72_2 + 0.0022983462408386304*g286_2 + 0.00030243956614094152*g287_2 + 0.00017522143559512698*g227_2 + 0.0028123885076645067*g69_2 + 0.0034850822615111973*g231_2 + -0.0067529052712627024*g294_2 + 0.0030783463317587837*g70_2);
    moment_arm[6 * kMaxElements + 57] = a2[0]; moment_arm[7 * kMaxElements + 57] = a2[1]; moment_arm[8 * kMaxElements + 57] = a2[2]; L[57] = a2[3]; }
  { const v4d a2 = (0.12627249910242783*e_len + -0.020457044871949114*g3_2 + -1.7506308044183902e-05*g232_2 + -0.0087846774093535383*g72_2 + 0.0008096565502635079*g282_2 + -0.0036355908004412881*g16_2 + -0.010095556069888323*g228_2 + 0.00022239059117673944*g285_2 + 4.9892257119510907e-05*g297_2 + 0.0024702582435744322*g227_2 + 0.0098398178484806632*g71_2 + 0.0036570856242027993*g19_2 + -0.0030968547952263882*g293_2) + (-0.00014563899258536998*g20_2 + 0.011185246123718316*g2_2 + 0.0089430396590532424*g4_2 + -0.028587912255787367*g294_2 + -0.005415791268786543*g234_2 + 0.0054464342955684968*g286_2 + 0.038453081590698032*g260_2 + -0.00065568272073619586*g15_2 + -0.0010556716760250742*g263_2 + -0.011031006380686135*g18_2 + 0.0079003286133649039*g296_2 + 0.0071707493379534566*g73_2);
    moment_arm[6 * kMaxElements + 58] = a2[0]; moment_arm[7 * kMaxElements + 58] = a2[1]; moment_arm[8 * kMaxElements + 58] = a2[2]; L[58] = a2[3]; }
  { const v4d a2 = (0.10806874034201941*e_len + 0.010103909010906824*g260_2 + 0.014645242520577554*g69_2 + -0.016350045648880662*g71_2 + -0.0082396486185728618*g3_2 + -0.0023292087671239249*g20_2 + -0.0015671134829819131*g15_2 + 0.014364605928116432*g290_2 + 0.00034604756989141481*g223_2 + -0.0024640370561738647*g296_2 + -0.0073840439017967534*g259_2) + (-0.019847943272352966*g17_2 + 0.010971828734870917*g2_2 + 0.010297910169325027*g4_2 + 0.019034125072836732*g231_2 + -0.0027445545765559342*g72_2 + -0.0036173526628551834*g225_2 + 0.0016521706764343672*g227_2 + 0.00086363288830983457*g281_2 + -0.01216887346226837*g286_2 + 0.0014192530003784977*g235_2 + -0.0030756427647405742*g18_2);
    moment_arm[6 * kMaxElements + 59] = a2[0]; moment_arm[7 * kMaxElements + 59] = a2[1]; moment_arm[8 * kMaxElements + 59] = a2[2]; L[59] = a2[3]; }
  { const v4d a2 = (0.09315877706334319*e_len + 3.5301682717440235e-06*g276_2 + 0.014045317956737226*g2_2 + -0.0019869033534603182*g19_2 + 0.017308766582397841*g3_2 + 8.7899297896903021e-05*g246_2 + -0.0057011711653609564*g20_2 + 0.00065297039062390204*g67_2 + -0.00039866840403668348*g281_2 + 0.0050789903196014809*g66_2 + 0.012951499842115521*g70_2 + 0.0016908677948509567*g256_2 + 0.002266794079587501*g232_2 + 0.0037816573019422962*g283_2 + -0.00091498997929429881*g293_2 + -0.00062460016921501624*g296_2) + (-0.011955670537629567*g18_2 + 0.013839796477325668*g4_2 + -0.0011120359171408259*g72_2 + -0.00029938818582666551*g253_2 + -0.0093555757120032876*g17_2 + 0.00069006645348913289*g287_2 + 0.0067495492404286931*g73_2 + 0.00015548144988738062*g227_2 + -0.0079145490701789875*g15_2 + -0.0010194872932794154*g68_2 + -0.0067051052843509901*g230_2 + -0.00096754092612443172*g278_2 + -0.0055557207906123751*g226_2 + -0.0015294651188885895*g221_2 + 0.0012068835300714413*g235_2);
    moment_arm[6 * kMaxElements + 60] = a2[0]; moment_arm[7 * kMaxElements + 60] = a2[1]; moment_arm[8 * kMaxElements + 60] = a2[2]; L[60] = a2[3]; }
  { const v4d a2 = (0.10960419230259845*e_len + 0.00065066127836002218*g225_2 + 0.014835303185936129*g2_2 + 0.00011372818869865523*g223_2 + -0.0001302627916489056*g276_2 + -0.011014370345540292*g17_2 + -0.0070707035476625978*g15_2 + 0.0004843747944508368*g286_2 + -0.0039755746328562457*g253_2 + 0.0027236697676880288*g221_2 + 0.004457223627491012*g231_2 + 0.00090901220449426078*g280_2 + 0.0017153848180389922*g282_2 + 0.0029464615106719822*g73_2 + -0.0025603315458946241*g294_2) + (-0.011067333136799791*g18_2 + 0.012521930587662832*g4_2 + -0.0027198171992369991*g291_2 + -0.0030448378539296331*g289_2 + 0.013510427769020729*g3_2 + -0.0060363963223625033*g74_2 + -0.0030250053729758801*g228_2 + -7.1941210837239467e-05*g255_2 + 0.003432569947129197*g257_2 + 0.0080900894464779639*g70_2 + 0.0089548306495720164*g260_2 + -0.0021990842566022221*g20_2 + -0.0024513247770276314*g277_2 + -0.00035075300406264923*g224_2);
    moment_arm[6 * kMaxElements + 61] = a2[0]; moment_arm[7 * kMaxElements + 61] = a2[1]; moment_arm[8 * kMaxElements + 61] = a2[2]; L[61] = a2[3]; }
  { const v4d a2 = (0.069572182077032738*e_len + 0.0020338858158611057*g225_2 + 0.014806649057972587*g2_2 + 0.00044942756124782758*g246_2 + -0.0051583545297041837*g20_2 + -0.0019378285623766957*g19_2 + 0.0079705365070204207*g3_2 + -0.0068643222112683639*g69_2 + 0.00083688731463800589*g286_2 + 0.0036982577336502199*g231_2 + 0.0010757785312054374*g272_2 + 0.003718277067390135*g262_2) + (-0.01068819018639932*g18_2 + 0.014916963429265235*g4_2 + 0.004554817613066176*g291_2 + -0.0014210331578339225*g289_2 + -0.00050764140234508474*g229_2 + -0.00046080370514730456*g253_2 + -0.005292442056554672*g15_2 + -0.0028655218423130698*g228_2 + 0.0059269623562030957*g70_2 + -0.0010142322045045898*g68_2 + -0.005288343057224104*g294_2 + 0.0029639052612313518*g73_2);
    moment_arm[6 * kMaxElements + 62] = a2[0]; moment_arm[7 * kMaxElements + 62] = a2[1]; moment_arm[8 * kMaxElements + 62] = a2[2]; L[62] = a2[3]; }
  { const v4d a2 = (0.092361352698177038*e_len + -0.008981844348677305*g20_2 + -0.010525880556632878*g2_2 + 0.0036541275866262663*g70_2 + -0.014713213780803725*g69_2 + -0.0074015361807005693*g232_2 + 0.0023611656373560505*g15_2 + 0.0044262685502845824*g291_2 + 0.00096869293613083729*g297_2 + 0.0011658761718553203*g73_2) + (0.059854005539370161*g3_2 + 0.0014139893629133973*g248_2 + 0.0029135707294001317*g18_2 + -0.0041293449600124515*g294_2 + 0.0076841181517891856*g253_2 + 0.0019730294367657606*g68_2 + -0.0040729426872828135*g282_2 + 0.014006391792384807*g17_2 + -0.0010840324416225594*g280_2);
    moment_arm[6 * kMaxElements + 63] = a2[0]; moment_arm[7 * kMaxElements + 63] = a2[1]; moment_arm[8 * kMaxElements + 63] = a2[2]; L[63] = a2[3]; }
  { const v4d a2 = (0.10727212207151879*e_len + -0.0059029031166689542*g20_2 + -0.0092762196803583274*g2_2 + 0.0008938799687981837*g234_2 + 0.0026426211217628233*g16_2 + -0.01322348803189731*g74_2) + (0.085306811107992375*g3_2 + -0.0074512078625834097*g69_2 + 0.00047020356636423663*g4_2 + 0.005925684050793357*g70_2 + 0.0030816991197714074*g229_2);
    moment_arm[6 * kMaxElements + 64] = a2[0]; moment_arm[7 * kMaxElements + 64] = a2[1]; moment_arm[8 * kMaxElements + 64] = a2[2]; L[64] = a2[3]; }
  { const v4d a2 = (0.10242720819885642*e_len + -0.0064234193206155069*g69_2 + -0.0077970890386103008*g2_2 + -0.0062887749111890127*g20_2 + -0.00041046837443973084*g234_2 + 0.0011661261324728523*g224_2 + -0.013534926140094647*g74_2) + (0.072079694227316665*g3_2 + 0.0017570180760558681*g75_2 + -0.0023797459439002162*g4_2 + -0.00079495040066098182*g250_2 + 0.013051275624802853*g19_2 + 0.0058665000041986035*g70_2);
    moment_arm[6 * kMaxElements + 65] = a2[0]; moment_arm[7 * kMaxElements + 65] = a2[1]; moment_arm[8 * kMaxElements + 65] = a2[2]; L[65] = a2[3]; }
  { const v4d a2 = (0.089122058405541812*e_len + -0.012145840975619675*g20_2 + -0.0079328841005514641*g69_2 + -0.0012410649188842355*g247_2 + -0.0027392883334447435*g253_2 + 0.0084701862753587404*g17_2 + 0.0010910202297975732*g282_2 + 0.0057655896475918237*g73_2 + -0.002544506913053619*g285_2 + -0.0066788413052626299*g4_2 + -0.016757954687237939*g234_2) + (0.043108470829151889*g3_2 + -0.011728770824699456*g2_2 + 0.0061809430448025145*g70_2 + 0.0060986104470848118*g260_2 + -0.0018134171610291682*g233_2 + 0.010262465769351329*g75_2 + 0.0019365094570209945*g66_2 + 0.003323725618563405*g224_2 + 0.0010311079006121813*g225_2 + 0.010983527426828279*g19_2);
    moment_arm[6 * kMaxElements + 66] = a2[0]; moment_arm[7 * kMaxElements + 66] = a2[1]; moment_arm[8 * kMaxElements + 66] = a2[2]; L[66] = a2[3]; }
  { const v4d a2 = (0.091052795741133938*e_len + 0.0027793616334225182*g73_2 + 0.0079770301564307585*g67_2 + 1.9338776165187145e-05*g291_2 + -0.0065654144022626844*g16_2 + 0.00039794971018928204*g281_2 + -0.010616243938079056*g15_2 + 0.00045405309804159107*g235_2 + 0.011045232314445277*g71_2 + 0.00018689287354360643*g259_2 + 0.0099136164326287784*g286_2 + 0.011509442698279807*g4_2 + -0.024610619256344529*g18_2 + 0.0021324422144315181*g248_2 + -0.0029184754309148678*g225_2 + -0.013731735530594336*g256_2) + (-0.021602044178405354*g3_2 + -0.0015824346941772456*g70_2 + 0.0027898414809563307*g230_2 + -0.0076980185554914619*g252_2 + 0.0035348187796360674*g280_2 + 0.00024136841865285167*g290_2 + -0.0092245274295004141*g19_2 + 0.00076000230283910977*g72_2 + 0.011285264085938444*g2_2 + -0.00033259485391723832*g276_2 + -0.0054104628182576383*g285_2 + -0.012288793818339359*g20_2 + 0.010940706189944164*g74_2 + 0.0039574267650379497*g68_2 + 0.0023996864250507379*g288_2);
    moment_arm[6 * kMaxElements + 67] = a2[0]; moment_arm[7 * kMaxElements + 67] = a2[1]; moment_arm[8 * kMaxElements + 67] = a2[2]; L[67] = a2[3]; }
  { const v4d a2 = (0.094982056840290638*e_len + -0.0021048645161224769*g73_2 + -0.0027411776082847368*g71_2 + -0.010217079828536531*g15_2 + 0.002505726011993047*g230_2 + -0.0068787491607574438*g20_2 + 0.00034958367254630553*g274_2 + 0.012210937450381161*g2_2 + -0.017187582981527134*g18_2 + -0.0051980788487949008*g255_2 + -0.00079523420482003465*g276_2 + -0.0035257309396143038*g225_2 + 0.0034219013017547676*g248_2) + (-0.021289269834287177*g3_2 + -0.001982720535005564*g16_2 + 0.0056013336027123705*g260_2 + 0.0038697089308848431*g285_2 + 0.0099333560257323979*g4_2 + 0.0013580564139935606*g68_2 + 0.0058440287490802737*g231_2 + -0.0061140460321746255*g72_2 + 0.0037451946818606008*g257_2 + 0.0078988155964678456*g67_2 + -0.0035220837031621614*g291_2 + -0.0050870885277981646*g256_2 + -0.00036980456985236511*g263_2);
    moment_arm[6 * kMaxElements + 68] = a2[0]; moment_arm[7 * kMaxElements + 68] = a2[1]; moment_arm[8 * kMaxElements + 68] = a2[2]; L[68] = a2[3]; }
  { const v4d a2 = (0.11572828009286683*e_len + 0.0045667288541326474*g232_2 + 0.0055644644372263106*g73_2 + -0.014615326976820029*g18_2 + -0.014698757723615341*g251_2 + 0.0069190952969535903*g280_2 + 0.0047209356879158101*g223_2 + -0.0085225467136463944*g2_2 + 0.0030402481637777598*g258_2 + -0.001323860891908551*g286_2 + 0.012781612638597247*g227_2 + 0.004206131923060334*g226_2 + -0.0036413644058339635*g291_2 + -0.003527423799356505*g284_2) + (-0.0035938471653815126*g19_2 + -0.018650808461072862*g3_2 + 0.00017607231074876441*g275_2 + -0.010622311788169041*g4_2 + -0.0054674683495409583*g15_2 + 0.0049742375142757499*g69_2 + -0.0011098287361955559*g247_2 + 0.0096068474056155533*g68_2 + -0.0011807087436943588*g72_2 + 0.0065511006574232953*g260_2 + -0.0064566908296833517*g17_2 + -0.0026242652956580672*g20_2 + -0.0012698391415856664*g274_2);
    moment_arm[6 * kMaxElements + 69] = a2[0]; moment_arm[7 * kMaxElements + 69] = a2[1]; moment_arm[8 * kMaxElements + 69] = a2[2]; L[69] = a2[3]; }
  { const v4d a2 = (0.093166268123164891*e_len + 0.0055991179645705326*g73_2 + 0.0004844831493485322*g292_2 + 0.011632505049179249*g74_2 + -0.0010259369284573994*g256_2 + -0.0071815875666773029*g15_2 + -0.0095672305746387527*g4_2 + -0.0091189934721973859*g2_2 + -0.014989922343292593*g18_2 + 0.0030843246896866544*g226_2 + 0.0017339732155755335*g225_2 + 0.0061418423031262184*g70_2 + 0.0024030798138597012*g75_2 + -0.00028504158848123438*g282_2) + (-0.022344523586272196*g3_2 + -0.0016497322896079298*g286_2 + -0.006327252729529209*g19_2 + -9.1103164615897165e-05*g276_2 + 0.0013701598465289688*g229_2 + -0.00044378131022167623*g275_2 + 0.0074157859457350045*g67_2 + -9.3472749778321832e-06*g247_2 + -0.0079670292047461441*g20_2 + -5.5539599200082677e-05*g297_2 + 0.0092502004900462311*g68_2 + 0.0018135036680734119*g233_2 + 0.0016975841619004356*g228_2 + -0.0008133711514898631*g273_2);
    moment_arm[6 * kMaxElements + 70] = a2[0]; moment_arm[7 * kMaxElements + 70] = a2[1]; moment_arm[8 * kMaxElements + 70] = a2[2]; L[70] = a2[3]; }
  { const v4d a2 = (0.075512624363119604*e_len + -0.0011018580777554772*g288_2 + 0.0063756266644584012*g75_2 + 0.0077666245513160238*g66_2 + -0.022454522303246655*g2_2 + 0.00023258224149381751*g68_2 + -6.3999682912662843e-05*g276_2 + 0.0216034651883317*g73_2 + -0.013999604958139743*g3_2 + 0.016915911422590156*g17_2 + 0.0040675124491382679*g275_2 + -0.0010469221122218785*g257_2 + 0.0045229097061252289*g229_2 + -0.019892807669968472*g256_2 + -0.00077519634112797734*g291_2 + 0.0055682663348327194*g286_2 + -0.0057984183054471611*g292_2 + 0.0091498841418506758*g223_2 + 0.023987787822662549*g224_2 + -0.0012728736351211196*g253_2) + (-0.0023604371620093842*g69_2 + -0.025695063623319057*g4_2 + 0.0053512635718339068*g231_2 + 0.026937388589330123*g70_2 + 0.00085540062716320763*g290_2 + -0.014592150685481278*g227_2 + 0.00070095023931651722*g18_2 + -0.010759351817611932*g245_2 + 0.010805502340229681*g71_2 + 0.0049975888040479054*g20_2 + -0.00058028302974155559*g72_2 + 0.0081166633552232949*g284_2 + -0.0014678905514465494*g277_2 + -0.0022155258301897623*g295_2 + 0.0051611743404759523*g273_2 + -0.012555438260336426*g254_2 + -0.012823655401597673*g246_2 + -0.018683902953961388*g247_2 + 0.003901090629486007*g274_2 + 0.0031348488726201129*g289_2);
    moment_arm[6 * kMaxElements + 71] = a2[0]; moment_arm[7 * kMaxElements + 71] = a2[1]; moment_arm[8 * kMaxElements + 71] = a2[2]; L[71] = a2[3]; }
  { const v4d a2 = (0.095899448903829648*e_len + 0.010312542499648752*g73_2 + 0.00047637998576463119*g263_2 + -0.017782594439989082*g4_2 + -0.002254219612197995*g71_2 + -0.0033002653810483931*g256_2 + -0.00043616533649805606*g279_2 + -0.0016200315989085392*g226_2 + 0.023807021254190465*g68_2 + 0.020096775087246846*g18_2 + -0.01781247794564032*g224_2 + 0.0047080979010611203*g247_2 + 0.0092320705527352085*g70_2 + 0.0035627390484921379*g289_2) + (0.012113190352319747*g17_2 + 0.0015046135701127325*g229_2 + -0.0045661670529193975*g261_2 + 0.014230864608345746*g20_2 + -0.016725417128874112*g2_2 + 0.013895732011913723*g15_2 + 0.0015563329626725232*g231_2 + -0.00026685738476175534*g276_2 + -0.012300298103124298*g67_2 + -0.0021637468069288001*g257_2 + -0.0030874524035429682*g3_2 + -0.0012109992813561744*g283_2 + -0.01076322286979*g230_2);
    moment_arm[6 * kMaxElements + 72] = a2[0]; moment_arm[7 * kMaxElements + 72] = a2[1]; moment_arm[8 * kMaxElements + 72] = a2[2]; L[72] = a2[3]; }
  { const v4d a2 = (0.1162491733308286*e_len + 0.0017880904253448364*g75_2 + -0.0015212855071285488*g289_2 + 8.0280156847778577e-05*g221_2 + 0.0039200150384532144*g275_2 + 0.00055020982181753846*g71_2 + -0.016477628993415004*g247_2 + 0.010311511577185935*g73_2 + 0.021398452162351516*g224_2 + 0.0044569733258832114*g20_2 + 0.0027477722322467209*g234_2 + -0.00064723586865370053*g291_2 + -0.00038345747725953807*g19_2) + (-0.02440482452541038*g4_2 + -0.0011542999123590151*g248_2 + 0.0031270502999528435*g66_2 + -0.00071038137786596589*g230_2 + -0.0208266284012503*g2_2 + -0.015237042861813271*g3_2 + 0.0044260114520036668*g17_2 + 0.01092745825301813*g70_2 + -0.0026059679271194323*g245_2 + -0.0022373005096017165*g286_2 + 0.0029751174277800694*g225_2 + 0.0025371376106306126*g228_2);
    moment_arm[6 * kMaxElements + 73] = a2[0]; moment_arm[7 * kMaxElements + 73] = a2[1]; moment_arm[8 * kMaxElements + 73] = a2[2]; L[73] = a2[3]; }
  { const v4d a2 = (0.11844492735459632*e_len + -0.025129606747833023*g2_2 + -0.0082319880330347043*g3_2 + 0.0018518448664789251*g17_2 + 0.0019104997433429397*g226_2 + 0.001223182247972403*g256_2 + 0.010451554070810571*g233_2 + 0.00089634996285656624*g235_2 + -0.0095766966119518373*g73_2 + -0.0015987012328949717*g15_2 + -0.0015415791551807842*g285_2) + (-0.024878029832348394*g4_2 + 0.0084673678190704052*g68_2 + -0.0056344399060740107*g258_2 + -9.292677140359599e-06*g75_2 + -0.0020010432347564401*g67_2 + 0.0018625621679692276*g280_2 + 0.0018569842053449762*g66_2 + 0.015076572361656255*g230_2 + -0.0026396835895730773*g290_2 + 0.0003069244371176765*g296_2);
    moment_arm[6 * kMaxElements + 74] = a2[0]; moment_arm[7 * kMaxElements + 74] = a2[1]; moment_arm[8 * kMaxElements + 74] = a2[2]; L[74] = a2[3]; }
  { const v4d a2 = (0.11909785774291502*e_len + -0.023051243737646665*g4_2 + 0.0013274451205255325*g281_2 + 0.010307458561895388*g224_2 + 0.00023778368920201153*g297_2 + -0.0055499874373101379*g288_2 + -0.00069722164857561469*g74_2 + 0.00023053770988363395*g249_2 + -0.002972513938988371*g280_2 + 0.0022760769727131949*g261_2 + -0.0018443332053863948*g286_2 + -0.00038317103172964286*g229_2 + 0.0091321891973702093*g254_2 + 0.0071860642303024289*g251_2 + 0.00043981697666137552*g274_2) + (-0.023730508930462125*g2_2 + 0.00041021638119618001*g19_2 + -0.0080709864407908505*g3_2 + 0.0035695363921185515*g258_2 + 5.4181954675696225e-05*g231_2 + -0.00036708945268882118*g15_2 + -0.0038442611189009944*g247_2 + 0.0012438551572325667*g228_2 + -0.0037440187760439201*g67_2 + -0.0079139733267132081*g71_2 + 0.00010034841625137004*g276_2 + 0.0017393315315317424*g234_2 + -0.00085427006294893195*g17_2 + 0.00087874716661838319*g244_2);
    moment_arm[6 * kMaxElements + 75] = a2[0]; moment_arm[7 * kMaxElements + 75] = a2[1]; moment_arm[8 * kMaxElements + 75] = a2[2]; L[75] = a2[3]; }
  { const v4d a2 = (0.14231247220402973*e_len + -0.024007763364639171*g4_2 + -0.010637418620020879*g230_2 + 0.00018453255604255683*g297_2 + -0.0031909411658428781*g231_2 + 0.0062017059115024907*g251_2 + -0.0034034173498247453*g16_2 + 0.00053826392101568503*g272_2 + -0.0044793078110146201*g285_2 + 0.017598119386501396*g258_2) + (-0.025075324151714484*g2_2 + 0.0077487487525613437*g224_2 + -0.0024758916064649022*g3_2 + -0.021387012076275587*g288_2 + -0.0027670365062369764*g67_2 + -0.0010867660537896057*g275_2 + 0.0037316678211110873*g233_2 + -0.0033756897870230789*g18_2 + 0.025082346232108758*g254_2);
    moment_arm[6 * kMaxElements + 76] = a2[0]; moment_arm[7 * kMaxElements + 76] = a2[1]; moment_arm[8 * kMaxElements + 76] = a2[2]; L[76] = a2[3]; }
  { const v4d a2 = (0.13702768362040874*e_len + -0.022070629335599508*g4_2 + 0.0048064851694220529*g254_2 + -0.017604889081575287*g16_2 + 0.0060421094327071795*g70_2 + -0.0025651758927928659*g293_2 + -0.00072455351437487642*g74_2 + 0.0020059096730458159*g244_2 + 9.8292639242005941e-05*g248_2 + -0.0014963916270082991*g67_2 + 0.0024101315288816106*g227_2) + (-0.021273207732021172*g2_2 + -0.00062449922333085049*g247_2 + 0.0012617487453210916*g235_2 + 0.015494614862044445*g68_2 + -0.0064334353364156084*g295_2 + -0.00044668152160643615*g282_2 + 0.01249735344777772*g261_2 + -0.0011115332412399083*g3_2 + 0.00086577256318387042*g253_2 + -0.0018908868647398199*g18_2 + -0.0021263949587997494*g284_2);
    moment_arm[6 * kMaxElements + 77] = a2[0]; moment_arm[7 * kMaxElements + 77] = a2[1]; moment_arm[8 * kMaxElements + 77] = a2[2]; L[77] = a2[3]; }
  { const v4d a2 = (0.095569274998744916*e_len + -0.021949135020791731*g4_2 + 0.0087898449949352104*g230_2 + -5.466098088532096e-05*g275_2 + 0.00033381622578192849*g297_2 + 0.0001380533006608781*g72_2 + -0.0031041137858471499*g20_2 + 0.0036075327869102801*g233_2 + 0.0099367007375615289*g252_2 + -0.0059140046091147869*g71_2 + -0.0022262669669770034*g3_2 + 0.0012457116015030631*g17_2 + -0.0018029485381495164*g15_2 + 0.0025356888519013302*g75_2) + (-0.022705598096231419*g2_2 + -0.00048729172327229535*g224_2 + -0.012023842938927441*g16_2 + 0.0075890020750033248*g254_2 + -0.0012951179521305865*g234_2 + 0.00097169737700152623*g74_2 + 0.0063442671839460752*g277_2 + -0.0046225272565112744*g256_2 + 0.012281735081611707*g68_2 + -2.9218221645802485e-06*g276_2 + -0.0036986242309063572*g281_2 + -0.0094914891283777534*g283_2 + 0.0013935900926752656*g66_2);
    moment_arm[6 * kMaxElements + 78] = a2[0]; moment_arm[7 * kMaxElements + 78] = a2[1]; moment_arm[8 * kMaxElements + 78] = a2[2]; L[78] = a2[3]; }
  { const v4d a2 = (0.113638441335471*e_len + -0.01911515746072296*g4_2 + 0.0018654110595232862*g226_2 + -0.0027215330779526451*g261_2 + -0.0015691326036427779*g293_2 + -0.0018253360881809091*g248_2 + 0.0023933075919173028*g66_2 + 0.0013939302788312292*g235_2 + -0.00113338257985225*g74_2 + 0.0084986299042356626*g233_2 + -0.00074055379008651978*g232_2 + -0.0015592531590919087*g286_2) + (-0.019838816192965979*g2_2 + 0.0036540482956609181*g69_2 + -0.0014166632533145374*g224_2 + 0.0044215513130951038*g70_2 + -0.015669999114320512*g16_2 + 0.0019309118934766484*g252_2 + -1.2658998881760881e-05*g281_2 + 0.003520278304367081*g230_2 + 0.0011902691951039201*g72_2 + 0.013237851417268033*g68_2 + 0.00062661233460643883*g276_2 + -0.00087337167190192566*g289_2);
    moment_arm[6 * kMaxElements + 79] = a2[0]; moment_arm[7 * kMaxElements + 79] = a2[1]; moment_arm[8 * kMaxElements + 79] = a2[2]; L[79] = a2[3]; }
  { const v4d a2 = (0.057239298997445336*e_len + 0.0041187842251138411*g73_2 + -0.0041590997607579968*g74_2 + -0.014814295180164963*g4_2 + 0.0042613827028632305*g228_2 + 0.019622013199696888*g72_2 + 0.0023063734815017898*g17_2 + 0.0031654937074198555*g70_2 + -0.0043681911000904711*g289_2 + -0.00160831720694548*g247_2 + 0.0029555112893679646*g257_2) + (0.013141570684921175*g3_2 + -0.0042862981899196651*g292_2 + 0.0027363859556309555*g66_2 + -0.017902562290747628*g2_2 + -0.0020827244466183957*g256_2 + -0.015899026466778488*g229_2 + 0.0035813664132466152*g224_2 + 0.00059737200512734005*g297_2 + 0.0032333115861007435*g253_2 + 0.011004463312373708*g258_2 + -0.0049939777280188025*g232_2);
    moment_arm[6 * kMaxElements + 80] = a2[0]; moment_arm[7 * kMaxElements + 80] = a2[1]; moment_arm[8 * kMaxElements + 80] = a2[2]; L[80] = a2[3]; }
  { const v4d a2 = (0.037199383928831625*e_len + 0.00095929729017872807*g75_2 + 0.0030447392678209623*g258_2 + -0.0067119311340543093*g230_2 + 0.00047075261924116589*g294_2 + 0.0020686071480918869*g221_2 + -0.012610378762051773*g4_2 + 0.0093916135646497402*g70_2 + -0.0029309087490361719*g278_2 + 0.00036970671128350798*g276_2 + -0.011097521450473945*g259_2 + 0.0027005527257158257*g15_2 + 0.0042644329999193976*g290_2) + (0.021236054593630184*g3_2 + -0.014778813758578511*g2_2 + 0.0012985144407455216*g20_2 + 0.0010771378610969313*g261_2 + 0.0051403245198481636*g16_2 + 0.010106064341414325*g73_2 + 0.010359026137261956*g19_2 + -0.0087956157798328508*g74_2 + -0.00076758092969578652*g253_2 + -0.00050893202946535509*g248_2 + 0.0025308674281596557*g71_2 + -0.0014524514444762512*g67_2 + -0.00043016187326383774*g224_2);
    moment_arm[6 * kMaxElements + 81] = a2[0]; moment_arm[7 * kMaxElements + 81] = a2[1]; moment_arm[8 * kMaxElements + 81] = a2[2]; L[81] = a2[3]; }
  { const v4d a2 = (0.39301401992035473*e_len + 0.00477417367876775*g73_2 + 0.0064505761963830708*g223_2 + -0.0068102179502176332*g20_2 + -0.003323405788122459*g66_2) + (-0.022726489452261571*g3_2 + 3.3580948373612267e-05*g4_2 + -0.018010270841932883*g18_2 + 0.0027941731667783473*g74_2 + 0.003919134872382944*g226_2); const v4d a3 = (-0.025688990657068134*g1_3 + -0.00050993446149439692*g62_3 + 0.0015854747048530838*g219_3 + 0.0015319899373271155*g0_3) + (0.0044832822912369719*g12_3 + -0.00034072478080398325*g218_3 + -0.016710805969772771*g13_3 + -8.3402520576651175e-05*g216_3);
    moment_arm[6 * kMaxElements + 82] = a2[0]; moment_arm[7 * kMaxElements + 82] = a2[1]; moment_arm[8 * kMaxElements + 82] = a2[2]; moment_arm[9 * kMaxElements + 82] = a3[0]; moment_arm[10 * kMaxElements + 82] = a3[1]; L[82] = a2[3] + a3[3]; }
  { const v4d a2 = (0.35352503809417579*e_len + -0.0028835086270963596*g232_2 + 0.0063902729850981912*g229_2 + 0.0024967555865351562*g233_2 + 0.0044625599574396706*g234_2 + 0.010748889251046974*g3_2) + (-0.039543911481044185*g19_2 + -0.00039120061642218919*g69_2 + 0.0010513260601565484*g67_2 + -0.0078749889504705958*g17_2 + -0.00027693154455234431*g220_2 + 0.0013758409759407374*g65_2); const v4d a3 = (-0.026058255851233308*g1_3 + 0.00098851427431825541*g219_3 + -0.00041948935654077124*g218_3 + -0.00027693154455234431*g220_3 + -0.00058563472061855314*g11_3) + (0.0044410487637062731*g0_3 + -0.02178241391038584*g13_3 + 0.0024318602900161813*g12_3 + 0.0013758409759407374*g65_3 + 0.003874222283257294*g63_3);
    moment_arm[6 * kMaxElements + 83] = a2[0]; moment_arm[7 * kMaxElements + 83] = a2[1]; moment_arm[8 * kMaxElements + 83] = a2[2]; moment_arm[9 * kMaxElements + 83] = a3[0]; moment_arm[10 * kMaxElements + 83] = a3[1]; L[83] = a2[3] + a3[3]; }
  { const v4d a2 = (0.35352503809417579*e_len + -0.0028835086270963596*g232_2 + 0.0063902729850981912*g229_2 + 0.0024967555865351562*g233_2 + 0.0044625599574396706*g234_2 + 0.010748889251046974*g3_2) + (-0.039543911481044185*g19_2 + -0.00039120061642218919*g69_2 + 0.0010513260601565484*g67_2 + -0.0078749889504705958*g17_2 + -0.00027693154455234431*g220_2 + 0.0013758409759407374*g65_2); const v4d a3 = (-0.026058255851233308*g1_3 + 0.00098851427431825541*g219_3 + -0.00041948935654077124*g218_3 + -0.00027693154455234431*g220_3 + -0.00058563472061855314*g11_3) + (0.0044410487637062731*g0_3 + -0.02178241391038584*g13_3 + 0.0024318602900161813*g12_3 + 0.0013758409759407374*g65_3 + 0.003874222283257294*g63_3);
    moment_arm[6 * kMaxElements + 84] = a2[0]; moment_arm[7 * kMaxElements + 84] = a2[1]; moment_arm[8 * kMaxElements + 84] = a2[2]; moment_arm[9 * kMaxElements + 84] = a3[0]; moment_arm[10 * kMaxElements + 84] = a3[1]; L[84] = a2[3] + a3[3]; }
  { const v4d a2 = (0.28810482745662963*e_len + -0.0014963532796749772*g225_2 + 0.0012621978471176545*g20_2 + -0.0090516803515194519*g72_2 + 0.028051818099328107*g19_2 + 0.0031334058079304024*g2_2) + (0.040383697740527719*g3_2 + 0.002316555133211154*g4_2 + 1.225328770015525e-05*g14_2 + 0.007683884841880438*g232_2 + -0.024041041142686764*g74_2); const v4d a3 = (0.018858723428750376*g1_3) + (1.225328770015525e-05*g14_3);
    moment_arm[6 * kMaxElements + 85] = a2[0]; moment_arm[7 * kMaxElements + 85] = a2[1]; moment_arm[8 * kMaxElements + 85] = a2[2]; moment_arm[9 * kMaxElements + 85] = a3[0]; moment_arm[10 * kMaxElements + 85] = a3[1]; L[85] = a2[3] + a3[3]; }
  { const v4d a2 = (0.29944073107803498*e_len + -0.001256113338338406*g234_2 + 0.0064687915319943511*g19_2 + 0.001298392582581722*g14_2) + (0.030756245851734327*g3_2 + -0.00090018278279695467*g225_2 + -0.010539570581817407*g74_2 + 0.0016714269032897184*g260_2); const v4d a3 = (0.018501387610506386*g1_3) + (0.001298392582581722*g14_3);
    moment_arm[6 * kMaxElements + 86] = a2[0]; moment_arm[7 * kMaxElements + 86] = a2[1]; moment_arm[8 * kMaxElements + 86] = a2[2]; moment_arm[9 * kMaxElements + 86] = a3[0]; moment_arm[10 * kMaxElements + 86] = a3[1]; L[86] = a2[3] + a3[3]; }
  { const v4d a2 = (0.32601804404529894*e_len + -0.0010958067729918623*g225_2 + -0.0012447014180999615*g20_2 + -0.0034890570386174407*g72_2 + 0.013945075203849836*g19_2) + (0.030169062719527431*g3_2 + 0.0040781567489444094*g4_2 + 0.0016261837497589932*g14_2 + 0.0033998483349239952*g232_2 + -0.013093258547500344*g74_2); const v4d a3 = (0.018349813622767958*g1_3) + (0.0016261837497589932*g14_3);
    moment_arm[6 * kMaxElements + 87] = a2[0]; moment_arm[7 * kMaxElements + 87] = a2[1]; moment_arm[8 * kMaxElements + 87] = a2[2]; moment_arm[9 * kMaxElements + 87] = a3[0]; moment_arm[10 * kMaxElements + 87] = a3[1]; L[87] = a2[3] + a3[3]; }
  { const v4d a2 = (0.32204768950797774*e_len + 0.00013605496168904929*g262_2 + 0.0053475158498315096*g4_2 + 0.0012302702320920132*g14_2 + -0.0070671311561727405*g74_2) + (0.032634702960076666*g3_2 + -0.00063741170743471275*g248_2 + -0.0035538838905914355*g20_2 + 0.00019703181324897873*g263_2 + 0.0010754891591418817*g229_2); const v4d a3 = (0.018521603599392124*g1_3) + (0.0012302702320920132*g14_3);
    moment_arm[6 * kMaxElements + 88] = a2[0]; moment_arm[7 * kMaxElements + 88] = a2[1]; moment_arm[8 * kMaxElements + 88] = a2[2]; moment_arm[9 * kMaxElements + 88] = a3[0]; moment_arm[10 * kMaxElements + 88] = a3[1]; L[88] = a2[3] + a3[3]; }
  { const v4d a0 = (0.24740418788957017*e_len + 0.038055112227712247*g162_0 + -0.017439958624513564*g174_0 + 0.091466366049021544*g9_0 + -0.046925634991789984*g205_0 + -0.011993791737047736*g142_0 + -0.0096450240503045109*g180_0 + 0.052635457357777457*g182_0 + -0.0096059435551668366*g137_0 + -0.020885138860971462*g57_0 + -0.0083755944887880084*g59_0 + 0.0059476949278624673*g131_0 + 0.013921840146148052*g37_0) + (0.011143597487185394*g190_0 + 0.028596850438743868*g8_0 + 0.12296503846243995*g10_0 + -0.082766040977262284*g138_0 + -0.0011392125574652726*g178_0 + -0.012538166788849611*g151_0 + -0.0013980939521897008*g193_0 + 0.0065758151990755404*g149_0 + -0.016672141109961732*g132_0 + 0.0054594351571122038*g122_0 + 0.0040669344437200715*g152_0 + -0.0091949573060449239*g123_0); const v4d a1 = (0.011143597487185394*g190_1 + 0.030575235615033901*g23_1 + -0.0080357353890594379*g91_1 + -0.038210811550407058*g111_1 + -0.019716670202636181*g104_1 + -0.082766040977262284*g138_1 + -0.02715520179546347*g116_1 + -0.01494005976005169*g112_1 + -0.077010448113244853*g92_1 + -0.019816138383966328*g81_1 + -0.016672141109961732*g132_1 + 0.0059476949278624673*g131_1) + (0.038055112227712247*g162_1 + 0.0078276023358124537*g102_1 + -0.017439958624513564*g174_1 + 0.10512002394612044*g34_1 + 0.030375559701584783*g5_1 + -0.021281076633851214*g106_1 + 0.01896388043513822*g26_1 + -0.015633167368778976*g87_1 + 0.052635457357777457*g182_1 + -0.0096059435551668366*g137_1 + 0.030878993907531554*g82_1); const v4d a2 = (0.030575235615033901*g23_2 + 0.0078276023358124537*g102_2 + -0.038210811550407058*g111_2 + -0.020453186956296322*g2_2 + -0.0011392125574652726*g178_2 + -0.021281076633851214*g106_2 + 0.01896388043513822*g26_2 + 0.0083671207087236132*g72_2 + -0.015633167368778976*g87_2 + 0.0045028373859967441*g75_2 + -0.0096450240503045109*g180_2 + -0.077010448113244853*g92_2 + 0.0023547932349054731*g73_2 + 0.0080437161572707496*g70_2 + -0.016672141109961732*g132_2 + 0.0054594351571122038*g122_2 + 0.0059476949278624673*g131_2 + 0.013921840146148052*g37_2) + (0.044911385213314552*g3_2 + -0.0080357353890594379*g91_2 + -0.019716670202636181*g104_2 + -0.014500982572679216*g20_2 + -0.011993791737047736*g142_2 + -0.02715520179546347*g116_2 + -0.0062400159170949163*g69_2 + -0.01494005976005169*g112_2 + -0.012538166788849611*g151_2 + -0.0091515489192571103*g74_2 + -0.0013980939521897008*g193_2 + -0.019816138383966328*g81_2 + 0.0065758151990755404*g149_2 + -0.0096059435551668366*g137_2 + 0.030878993907531554*g82_2 + 0.0040669344437200715*g152_2 + -0.0091949573060449239*g123_2);
    moment_arm[0 * kMaxElements + 89] = a0[0]; moment_arm[1 * kMaxElements + 89] = a0[1]; moment_arm[2 * kMaxElements + 89] = a0[2]; moment_arm[3 * kMaxElements + 89] = a1[0]; moment_arm[4 * kMaxElements + 89] = a1[1]; moment_arm[5 * kMaxElements + 89] = a1[2]; moment_arm[6 * kMaxElements + 89] = a2[0]; moment_arm[7 * kMaxElements + 89] = a2[1]; moment_arm[8 * kMaxElements + 89] = a2[2]; L[89] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.27366494811219594*e_len + -0.11887377043291762*g190_0 + 0.11806411998278876*g9_0 + -0.0064628915061099171*g142_0 + 0.11697472219896797*g55_0 + -0.0016907135426104543*g160_0 + 0.24861166332354909*g56_0 + 0.053379499443361733*g8_0 + -0.32788006094110883*g54_0 + 0.028671173774807959*g199_0 + 0.08394238896896794*g139_0 + -0.025403256185640384*g188_0 + -0.071593576159116282*g167_0 + -0.010838175715696922*g193_0 + -0.010742122314623063*g178_0 + -0.016013745735160047*g151_0 + 3.7025928330532406e-05*g154_0 + 0.028531032489533991*g131_0) + (-0.0065743158600366303*g49_0 + 0.48602782441413056*g189_0 + 0.032987592002964417*g37_0 + -0.008755327563473185*g147_0 + 0.037096508087542411*g146_0 + -0.072673232923201048*g203_0 + -0.057473318921447365*g169_0 + -0.018371434258278717*g184_0 + 0.014030686747543731*g159_0 + -0.039902354447559664*g132_0 + 0.004831426694010689*g148_0 + -0.023326219430108337*g183_0 + -0.080478288989385055*g191_0 + -0.028204582042155396*g123_0 + -0.00065400215232642664*g150_0 + 0.0049206829235803303*g177_0 + -0.0066251308762305047*g187_0 + 0.014911885389045181*g141_0); const v4d a1 = (-0.11887377043291762*g190_1 + 0.0080078953578969266*g105_1 + 0.11697472219896797*g55_1 + -0.0016907135426104543*g160_1 + -0.014342903541039613*g95_1 + -0.034818566755504599*g94_1 + 0.052541816398453026*g34_1 + 0.061430090473715657*g93_1 + -0.017887192598858643*g104_1 + -0.1528492426512921*g113_1 + -0.0084238034384576353*g79_1 + 0.007107687314885874*g85_1 + -0.039902354447559664*g132_1 + 0.134340042471743*g114_1 + -0.025403256185640384*g188_1 + -0.023326219430108337*g183_1 + -0.071593576159116282*g167_1 + -0.019819347742733515*g31_1 + 0.027559358354008318*g86_1 + 3.7025928330532406e-05*g154_1 + -0.0066251308762305047*g187_1 + 0.028531032489533991*g131_1) + (0.48602782441413056*g189_1 + -0.028291875639378818*g25_1 + 0.037096508087542411*g146_1 + 0.042102506576764086*g23_1 + -0.072673232923201048*g203_1 + 0.24861166332354909*g56_1 + -0.057473318921447365*g169_1 + -0.018371434258278717*g184_1 + -0.32788006094110883*g54_1 + -0.024609794607271637*g110_1 + 0.014030686747543731*g159_1 + -0.055320299276312851*g96_1 + 0.08394238896896794*g139_1 + -0.019971411798908458*g32_1 + -0.048277983092452653*g111_1 + 0.08207159741888935*g6_1 + 0.024802499855283728*g107_1 + -0.080478288989385055*g191_1 + -0.010797971511054405*g76_1 + -0.01587674571559209*g87_1 + -0.0037146259532180982*g102_1); const v4d a2 = (0.032987592002964417*g37_2 + -0.0064628915061099171*g142_2 + -0.0016907135426104543*g160_2 + -0.014342903541039613*g95_2 + 0.061430090473715657*g93_2 + -0.018371434258278717*g184_2 + -0.024609794607271637*g110_2 + 0.014030686747543731*g159_2 + 0.007107687314885874*g85_2 + -0.039902354447559664*g132_2 + -0.019971411798908458*g32_2 + 0.004831426694010689*g148_2 + -0.048277983092452653*g111_2 + 0.024802499855283728*g107_2 + -0.010838175715696922*g193_2 + 0.027559358354008318*g86_2 + -0.010742122314623063*g178_2 + -0.00065400215232642664*g150_2 + 0.0049206829235803303*g177_2 + -0.010797971511054405*g76_2 + -0.01587674571559209*g87_2 + -0.0037146259532180982*g102_2 + 0.014911885389045181*g141_2) + (0.0080078953578969266*g105_2 + -0.028291875639378818*g25_2 + 0.042102506576764086*g23_2 + 0.042254768231858003*g3_2 + 0.0075072912840728834*g19_2 + -0.017887192598858643*g104_2 + -0.0084238034384576353*g79_2 + 0.028671173774807959*g199_2 + -0.055320299276312851*g96_2 + -0.012352235530082552*g74_2 + -0.026375628541896092*g2_2 + -0.025403256185640384*g188_2 + -0.023326219430108337*g183_2 + -0.019819347742733515*g31_2 + 0.0084146010124153282*g68_2 + -0.028204582042155396*g123_2 + 0.007741157997705899*g72_2 + -0.016013745735160047*g151_2 + 0.0031441337945592408*g70_2 + 3.7025928330532406e-05*g154_2 + -0.0066251308762305047*g187_2 + 0.028531032489533991*g131_2);
    moment_arm[0 * kMaxElements + 90] = a0[0]; moment_arm[1 * kMaxElements + 90] = a0[1]; moment_arm[2 * kMaxElements + 90] = a0[2]; moment_arm[3 * kMaxElements + 90] = a1[0]; moment_arm[4 * kMaxElements + 90] = a1[1]; moment_arm[5 * kMaxElements + 90] = a1[2]; moment_arm[6 * kMaxElements + 90] = a2[0]; moment_arm[7 * kMaxElements + 90] = a2[1]; moment_arm[8 * kMaxElements + 90] = a2[2]; L[90] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.28820755838273349*e_len + -0.041329738647023745*g190_0 + 0.079412581935069365*g134_0 + 0.019240365324253623*g187_0 + 0.027616954080222942*g211_0 + -0.032186844141963933*g123_0 + -0.012725955720965505*g178_0 + -0.022313484580468002*g151_0 + 0.0094229190863981769*g206_0 + 0.24997748363130357*g48_0 + 0.0093724041329030748*g125_0 + 0.021894503339244125*g136_0 + 0.0053611625298172864*g158_0 + -0.013371725415739425*g171_0 + -0.058783896724561101*g186_0 + 0.044954708813339558*g209_0 + 0.026800276944852146*g201_0) + (0.089673754808148362*g9_0 + 0.046087463466354894*g37_0 + 0.023207622098047789*g8_0 + -0.0064718715251136233*g197_0 + -0.023956365505334844*g154_0 + 0.0084243380439344567*g51_0 + 0.089262088214341742*g10_0 + 0.058980548941820699*g133_0 + -0.0014104574057256301*g168_0 + 0.00085351133080242673*g193_0 + -0.22304201378292082*g163_0 + -0.017751996660949062*g194_0 + 0.010004695438210601*g143_0 + -0.064518355646868031*g157_0 + -0.012097009603491088*g165_0 + -0.013735880636135638*g135_0); const v4d a1 = (-0.041329738647023745*g190_1 + 0.079412581935069365*g134_1 + 0.028898151948008884*g86_1 + 0.027616954080222942*g211_1 + -0.023956365505334844*g154_1 + -0.1052892403740897*g28_1 + 0.10742407122974898*g34_1 + -0.0014104574057256301*g168_1 + -0.22304201378292082*g163_1 + 0.021894503339244125*g136_1 + -0.064518355646868031*g157_1 + -0.0043562260261157315*g25_1 + -0.0079050632612317068*g81_1 + -0.039834122008695676*g96_1 + 0.072555535155779394*g114_1 + -0.017773847350859084*g110_1 + 0.026800276944852146*g201_1) + (0.0093326048517161902*g5_1 + 0.019240365324253623*g187_1 + -0.0064718715251136233*g197_1 + -0.028705308518769308*g104_1 + 0.030291055521359318*g80_1 + 0.028966020304030698*g97_1 + 0.058980548941820699*g133_1 + 0.24997748363130357*g48_1 + 0.022374923400170985*g91_1 + 0.0053611625298172864*g158_1 + -0.058783896724561101*g186_1 + -0.011993871806578729*g112_1 + -0.020777531899214489*g87_1 + 0.044954708813339558*g209_1 + -0.013735880636135638*g135_1 + -0.0086664711289038861*g89_1); const v4d a2 = (0.046087463466354894*g37_2 + -0.0079326437474921078*g74_2 + 0.028898151948008884*g86_2 + -0.023956365505334844*g154_2 + 0.030291055521359318*g80_2 + 0.0084243380439344567*g51_2 + 0.028966020304030698*g97_2 + 0.058980548941820699*g133_2 + 0.00085351133080242673*g193_2 + 0.022374923400170985*g91_2 + 0.021894503339244125*g136_2 + -0.012395272266853399*g4_2 + 0.0053611625298172864*g158_2 + 0.0057443930102251293*g70_2 + 0.0060346115599876297*g68_2 + -0.011993871806578729*g112_2 + -0.0079050632612317068*g81_2 + -0.039834122008695676*g96_2 + -0.0086664711289038861*g89_2) + (0.028158445357707777*g3_2 + 0.019240365324253623*g187_2 + -0.028705308518769308*g104_2 + 0.0077497407950360567*g72_2 + -0.032186844141963933*g123_2 + -0.012725955720965505*g178_2 + -0.022313484580468002*g151_2 + 0.0094229190863981769*g206_2 + 0.0093724041329030748*g125_2 + 0.012728751175369547*g19_2 + -0.017751996660949062*g194_2 + -0.018209115645643644*g2_2 + 0.010004695438210601*g143_2 + -0.013371725415739425*g171_2 + -0.0043562260261157315*g25_2 + -0.012097009603491088*g165_2 + -0.020777531899214489*g87_2 + -0.017773847350859084*g110_2);
    moment_arm[0 * kMaxElements + 91] = a0[0]; moment_arm[1 * kMaxElements + 91] = a0[1]; moment_arm[2 * kMaxElements + 91] = a0[2]; moment_arm[3 * kMaxElements + 91] = a1[0]; moment_arm[4 * kMaxElements + 91] = a1[1]; moment_arm[5 * kMaxElements + 91] = a1[2]; moment_arm[6 * kMaxElements + 91] = a2[0]; moment_arm[7 * kMaxElements + 91] = a2[1]; moment_arm[8 * kMaxElements + 91] = a2[2]; L[91] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.30395652187608385*e_len + -0.028271714256390766*g189_0 + 0.064511516318140116*g37_0 + 0.062810170397935419*g170_0 + -0.01075123726950385*g155_0 + -0.0052595367112129587*g177_0 + 0.011823968587351522*g184_0 + 0.042438435449287687*g174_0 + -0.034372277260405475*g50_0 + -0.012962082873108889*g126_0 + -0.018774533514456061*g142_0 + -0.10709296216763906*g175_0 + -0.022384519080230533*g123_0 + 0.0087077071857515394*g125_0 + 0.01123074078082918*g164_0) + (0.202198101264184*g9_0 + -0.10537163450010879*g162_0 + -0.23554919547757658*g55_0 + -0.028161595868732927*g160_0 + 0.034665639403068792*g42_0 + -0.0067474534926243888*g207_0 + -0.016904304372680073*g147_0 + -0.17758306495977716*g157_0 + -0.30391669542327709*g186_0 + -0.06116032659325011*g48_0 + 0.019806048739635981*g192_0 + 0.059767276583390275*g153_0 + 0.016771963396370174*g10_0 + -0.077335978125669447*g205_0 + -0.0069151129132279639*g150_0); const v4d a1 = (-0.028271714256390766*g189_1 + -0.23554919547757658*g55_1 + -0.01075123726950385*g155_1 + 0.020398712354251832*g111_1 + 0.011823968587351522*g184_1 + -0.17758306495977716*g157_1 + 0.050123317433283986*g33_1 + -0.06116032659325011*g48_1 + -0.009356363146716732*g76_1 + 0.09792448049782318*g98_1 + -0.011860094723366382*g92_1 + 0.059767276583390275*g153_1 + 0.0044649038916698483*g82_1 + -0.012992312450826307*g81_1) + (-0.10537163450010879*g162_1 + -0.028161595868732927*g160_1 + 0.0235925727990813*g23_1 + -0.011571107886046924*g104_1 + 0.042438435449287687*g174_1 + -0.30391669542327709*g186_1 + 0.0020053276961672956*g114_1 + 0.021425837040600811*g113_1 + 0.031657492393490444*g93_1 + 0.014293660800032767*g103_1 + -0.010829083861307926*g120_1 + -0.032174247868459016*g87_1 + 0.041165273802396138*g26_1 + 0.021178803760854049*g80_1); const v4d a2 = (0.064511516318140116*g37_2 + -0.0064175009525509197*g18_2 + 0.0235925727990813*g23_2 + -0.0052595367112129587*g177_2 + -0.034519193218294872*g16_2 + -0.011571107886046924*g104_2 + 0.016259664376669213*g68_2 + -0.009356363146716732*g76_2 + -0.018774533514456061*g142_2 + 0.014293660800032767*g103_2 + -0.032174247868459016*g87_2 + 0.0044649038916698483*g82_2 + 0.0087077071857515394*g125_2 + -0.0069151129132279639*g150_2 + 0.021178803760854049*g80_2) + (-0.028161595868732927*g160_2 + -0.01075123726950385*g155_2 + 0.03582293186232214*g3_2 + 0.020398712354251832*g111_2 + -0.0067474534926243888*g207_2 + 0.011823968587351522*g184_2 + -0.012962082873108889*g126_2 + 0.031657492393490444*g93_2 + 0.019806048739635981*g192_2 + -0.011860094723366382*g92_2 + -0.022384519080230533*g123_2 + 0.041165273802396138*g26_2 + 0.01123074078082918*g164_2 + -0.012992312450826307*g81_2);
    moment_arm[0 * kMaxElements + 92] = a0[0]; moment_arm[1 * kMaxElements + 92] = a0[1]; moment_arm[2 * kMaxElements + 92] = a0[2]; moment_arm[3 * kMaxElements + 92] = a1[0]; moment_arm[4 * kMaxElements + 92] = a1[1]; moment_arm[5 * kMaxElements + 92] = a1[2]; moment_arm[6 * kMaxElements + 92] = a2[0]; moment_arm[7 * kMaxElements + 92] = a2[1]; moment_arm[8 * kMaxElements + 92] = a2[2]; L[92] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.25961741839132774*e_len + -0.065425679714467805*g189_0 + 0.094179905014396978*g47_0 + -0.039044260643969729*g154_0 + -0.049797152979018384*g160_0 + 0.01189615085237272*g208_0 + -0.031335340609123789*g198_0 + -0.0049233480219093304*g150_0 + 0.034539104603571798*g129_0 + -0.02923774003491126*g159_0 + 0.038669144363341235*g131_0 + 0.025239002757081054*g164_0 + 0.024393500210601941*g57_0 + -0.053369290327503933*g173_0) + (0.22106668691663939*g9_0 + 0.065672631457235162*g37_0 + 0.04457443164285841*g10_0 + -0.017562369642628018*g123_0 + -0.04262545987603699*g155_0 + -0.024507750047640591*g161_0 + -0.016730020521289121*g183_0 + -0.066496623450962633*g157_0 + -0.015003585160052395*g142_0 + -0.07969984656999847*g138_0 + 0.042228220892544827*g190_0 + -0.041974705050638189*g176_0 + -0.02701208738962103*g209_0); const v4d a1 = (-0.065425679714467805*g189_1 + 0.10156352400974371*g118_1 + -0.039044260643969729*g154_1 + -0.067386515742550473*g24_1 + -0.049797152979018384*g160_1 + -0.039286844298044611*g33_1 + -0.016730020521289121*g183_1 + 0.041561421794500772*g93_1 + 0.034539104603571798*g129_1 + -0.07969984656999847*g138_1 + 0.038669144363341235*g131_1 + 0.042228220892544827*g190_1 + -0.02701208738962103*g209_1 + -0.053369290327503933*g173_1) + (0.094179905014396978*g47_1 + 0.019450997267630041*g80_1 + -0.003410789286815243*g86_1 + -0.010764808766547201*g31_1 + -0.04262545987603699*g155_1 + -0.024507750047640591*g161_1 + -0.066496623450962633*g157_1 + 0.073829767169633589*g26_1 + -0.02923774003491126*g159_1 + 0.033298934294580682*g91_1 + -0.020065302173148235*g87_1 + 0.0043445121698202811*g100_1 + 0.033110549003911874*g96_1 + -0.020725301721675259*g92_1); const v4d a2 = (0.065672631457235162*g37_2 + 0.020739194909517835*g17_2 + -0.003410789286815243*g86_2 + -0.010764808766547201*g31_2 + -0.04262545987603699*g155_2 + -0.0058426592274952683*g69_2 + -0.030152238283859153*g16_2 + 0.041561421794500772*g93_2 + 0.034539104603571798*g129_2 + -0.02923774003491126*g159_2 + 0.033298934294580682*g91_2 + 0.038669144363341235*g131_2 + 0.025239002757081054*g164_2 + 0.0043445121698202811*g100_2 + -0.020725301721675259*g92_2) + (0.019450997267630041*g80_2 + -0.039044260643969729*g154_2 + -0.017562369642628018*g123_2 + -0.049797152979018384*g160_2 + 0.01189615085237272*g208_2 + -0.016730020521289121*g183_2 + -0.0049233480219093304*g150_2 + 0.073829767169633589*g26_2 + -0.015003585160052395*g142_2 + 0.01246917535181997*g68_2 + 0.028633246942895554*g3_2 + -0.020065302173148235*g87_2 + -0.0027644223887032882*g4_2 + 0.033110549003911874*g96_2);
    moment_arm[0 * kMaxElements + 93] = a0[0]; moment_arm[1 * kMaxElements + 93] = a0[1]; moment_arm[2 * kMaxElements + 93] = a0[2]; moment_arm[3 * kMaxElements + 93] = a1[0]; moment_arm[4 * kMaxElements + 93] = a1[1]; moment_arm[5 * kMaxElements + 93] = a1[2]; moment_arm[6 * kMaxElements + 93] = a2[0]; moment_arm[7 * kMaxElements + 93] = a2[1]; moment_arm[8 * kMaxElements + 93] = a2[2]; L[93] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.24832745478143969*e_len + -0.00044865882015113722*g189_0 + 0.1571289773551682*g47_0 + 0.074792147647733301*g37_0 + 0.057198191227860309*g201_0 + 0.016934860010817555*g200_0 + -0.0089227184214686756*g198_0 + -0.022495183179735048*g142_0 + 0.033558123499656242*g133_0 + -0.089551347285835831*g154_0 + -0.055438369598238217*g175_0 + 0.052010936583563629*g211_0 + 0.033571046760745578*g131_0 + 0.016518464822996976*g164_0 + 0.0030786605277119627*g168_0 + -0.10553890184007517*g55_0 + -0.061511725350633546*g183_0 + 0.035022588473655802*g138_0) + (0.23910782924874921*g9_0 + 0.021197299719604934*g57_0 + -0.022042690981585403*g123_0 + 0.020292316765341486*g184_0 + 0.011524388803347217*g52_0 + -0.049738626090987149*g159_0 + -0.010813744618805701*g45_0 + 0.10470889752200314*g56_0 + -0.0073549513209779146*g139_0 + -0.032726316341182601*g128_0 + -0.042244857025517779*g187_0 + 0.032667862405032271*g42_0 + -0.054591921379723365*g173_0 + -0.024702419819932427*g151_0 + 0.14965577363155536*g190_0 + 0.031864586085986503*g166_0 + -0.085364799893769994*g186_0); const v4d a1 = (-0.00044865882015113722*g189_1 + 0.021627453880458489*g80_1 + 0.020292316765341486*g184_1 + 0.043704313882293712*g5_1 + -0.017243221549073373*g104_1 + 0.03371054393298533*g34_1 + 0.033558123499656242*g133_1 + -0.050522537394793267*g92_1 + -0.032726316341182601*g128_1 + -0.042244857025517779*g187_1 + 0.033571046760745578*g131_1 + 0.0030786605277119627*g168_1 + 0.010039771514554086*g95_1 + -0.10553890184007517*g55_1 + -0.085364799893769994*g186_1) + (0.1571289773551682*g47_1 + 0.014019417547841076*g111_1 + 0.057198191227860309*g201_1 + -0.049738626090987149*g159_1 + 0.02459830592487542*g97_1 + 0.10470889752200314*g56_1 + -0.0073549513209779146*g139_1 + -0.089551347285835831*g154_1 + 0.028217768502278265*g91_1 + 0.052010936583563629*g211_1 + -0.054591921379723365*g173_1 + -0.014956542799034826*g89_1 + 0.14965577363155536*g190_1 + -0.061511725350633546*g183_1 + 0.035022588473655802*g138_1); const v4d a2 = (0.033903907066401111*g17_2 + 0.021627453880458489*g80_2 + 0.014019417547841076*g111_2 + 0.011524388803347217*g52_2 + -0.049738626090987149*g159_2 + -0.017243221549073373*g104_2 + 0.006346413077684355*g72_2 + -0.010813744618805701*g45_2 + -0.007940138002338764*g69_2 + 0.033558123499656242*g133_2 + -0.089551347285835831*g154_2 + 0.028217768502278265*g91_2 + 0.033571046760745578*g131_2 + -0.024702419819932427*g151_2 + 0.010039771514554086*g95_2 + -0.061511725350633546*g183_2) + (-0.022042690981585403*g123_2 + 0.074792147647733301*g37_2 + 0.020292316765341486*g184_2 + 0.016934860010817555*g200_2 + 0.00092481357738335285*g2_2 + 0.02459830592487542*g97_2 + -0.028937267134218948*g16_2 + -0.022495183179735048*g142_2 + 0.01221090175044472*g68_2 + -0.050522537394793267*g92_2 + -0.032726316341182601*g128_2 + -0.042244857025517779*g187_2 + 0.016518464822996976*g164_2 + -0.014956542799034826*g89_2 + 0.031864586085986503*g166_2);
    moment_arm[0 * kMaxElements + 94] = a0[0]; moment_arm[1 * kMaxElements + 94] = a0[1]; moment_arm[2 * kMaxElements + 94] = a0[2]; moment_arm[3 * kMaxElements + 94] = a1[0]; moment_arm[4 * kMaxElements + 94] = a1[1]; moment_arm[5 * kMaxElements + 94] = a1[2]; moment_arm[6 * kMaxElements + 94] = a2[0]; moment_arm[7 * kMaxElements + 94] = a2[1]; moment_arm[8 * kMaxElements + 94] = a2[2]; L[94] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.14601456923143266*e_len + 0.079115525887205024*g162_0 + -0.033143569849378517*g142_0 + 0.0026163099781229232*g199_0 + 0.036738236885538206*g187_0 + -0.1403132469288218*g135_0 + -0.0075061195220540947*g140_0 + -0.1303214122552554*g41_0 + -0.040097157351797669*g176_0 + -0.1555093126460195*g139_0 + 0.04519347550166096*g166_0 + -0.020800326507805143*g123_0 + -0.0077412321846331662*g179_0 + 0.011714362461474349*g122_0 + -0.063176804276280113*g185_0 + -0.0032992284049202262*g151_0) + (0.18836770849686629*g9_0 + -0.011293368241020629*g52_0 + 0.034867172119531054*g146_0 + 0.0757258714813481*g214_0 + 0.11887109736216886*g59_0 + 0.072243865699440163*g37_0 + 0.060401296998220305*g127_0 + -0.018256412914996294*g152_0 + -0.16233726576020935*g173_0 + 0.023867072697335529*g42_0 + 0.05504641072851485*g136_0 + -0.010390417092895992*g188_0 + -0.072960510177422444*g50_0 + -0.070444368742158703*g202_0 + -0.067251447609441767*g156_0 + 0.03062124421192201*g194_0); const v4d a1 = (0.079115525887205024*g162_1 + -0.23346290606940329*g99_1 + -0.0091420152358246895*g78_1 + 0.052533452492115308*g80_1 + -0.015414810143440452*g93_1 + -0.1403132469288218*g135_1 + -0.021113661524781214*g104_1 + 0.087282521172204544*g107_1 + -0.013249581723086105*g88_1 + -0.02785987713682618*g90_1 + -0.038029754634462606*g108_1 + -0.1555093126460195*g139_1 + 0.05504641072851485*g136_1 + -0.010390417092895992*g188_1 + -0.063176804276280113*g185_1 + 0.0090419151505478565*g89_1) + (0.034867172119531054*g146_1 + 0.036738236885538206*g187_1 + -0.074391725371324144*g33_1 + -0.20988453607157609*g29_1 + -0.029029097111676335*g31_1 + -0.052450402382795885*g106_1 + -0.0075061195220540947*g140_1 + 0.060401296998220305*g127_1 + -0.1303214122552554*g41_1 + 0.023539014454012061*g86_1 + -0.16233726576020935*g173_1 + 0.023169449233418633*g95_1 + 0.0019066414323173297*g32_1 + -0.070444368742158703*g202_1 + -0.067251447609441767*g156_1 + 0.0069054603828256128*g6_1); const v4d a2 = (-0.011293368241020629*g52_2 + -0.033143569849378517*g142_2 + 0.036738236885538206*g187_2 + -0.026153625737432587*g2_2 + 0.052533452492115308*g80_2 + -0.015414810143440452*g93_2 + -0.052450402382795885*g106_2 + 0.072243865699440163*g37_2 + 0.060401296998220305*g127_2 + -0.02785987713682618*g90_2 + 0.023539014454012061*g86_2 + 0.030585967822532718*g72_2 + -0.036684184190651885*g19_2 + 0.040315373225881863*g3_2 + 0.05504641072851485*g136_2 + 0.0019066414323173297*g32_2 + -0.0077412321846331662*g179_2 + 0.0090419151505478565*g89_2 + -0.016456014673034217*g71_2 + 0.0036772664491863398*g68_2) + (-0.023956078408306661*g4_2 + 0.0026163099781229232*g199_2 + -0.0070005578504013328*g69_2 + -0.0091420152358246895*g78_2 + 0.019194255222691799*g17_2 + -0.029029097111676335*g31_2 + -0.021113661524781214*g104_2 + 0.087282521172204544*g107_2 + -0.013249581723086105*g88_2 + 0.0071381909866654403*g15_2 + -0.038029754634462606*g108_2 + -0.018256412914996294*g152_2 + 0.023169449233418633*g95_2 + 0.04519347550166096*g166_2 + -0.020800326507805143*g123_2 + -0.010390417092895992*g188_2 + 0.011714362461474349*g122_2 + -0.0032992284049202262*g151_2 + 0.014034692612735282*g18_2 + 0.03062124421192201*g194_2);
    moment_arm[0 * kMaxElements + 95] = a0[0]; moment_arm[1 * kMaxElements + 95] = a0[1]; moment_arm[2 * kMaxElements + 95] = a0[2]; moment_arm[3 * kMaxElements + 95] = a1[0]; moment_arm[4 * kMaxElements + 95] = a1[1]; moment_arm[5 * kMaxElements + 95] = a1[2]; moment_arm[6 * kMaxElements + 95] = a2[0]; moment_arm[7 * kMaxElements + 95] = a2[1]; moment_arm[8 * kMaxElements + 95] = a2[2]; L[95] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.15853526335797397*e_len + 0.02937101220766003*g54_0 + -0.010114164984912428*g44_0 + -0.013441057650104648*g123_0 + -0.034274465690691154*g128_0 + -0.10392894538156829*g168_0 + -0.011144602794530492*g150_0 + -0.043743991378088029*g10_0 + -0.025933191268230203*g162_0 + -0.0091720819749502667*g126_0 + 0.048319846544610169*g37_0 + -0.042126419629985361*g154_0 + -0.010255283712784159*g121_0 + 0.011456521073065164*g155_0 + -0.080148506859961041*g48_0) + (0.19563787973779231*g9_0 + 0.030019523538494547*g159_0 + -0.048653859365217586*g130_0 + 0.099493741056387835*g47_0 + 0.0048597201592666204*g171_0 + -0.04777458032788854*g176_0 + -0.037113692737736438*g195_0 + 0.073559631438280634*g40_0 + 0.016088084791786708*g125_0 + 0.016996141960956401*g146_0 + -0.043960390874211747*g165_0 + 0.011334674092221839*g187_0 + 0.020906268826162363*g141_0 + -0.015826782810730279*g36_0); const v4d a1 = (-0.041406199065368909*g114_1 + -0.10247627259331378*g92_1 + 0.18360663451013148*g113_1 + 0.034063504113431793*g80_1 + 0.099493741056387835*g47_1 + 0.030750509103670831*g86_1 + 0.019813699570570102*g109_1 + 0.013148109026091256*g112_1 + -0.049804715123951307*g116_1 + -0.029668188742767505*g79_1 + -0.037113692737736438*g195_1 + -0.044629266165454026*g87_1 + 0.020985953019582296*g78_1 + -0.033893892861076566*g98_1 + -0.042126419629985361*g154_1 + -0.026889566032702698*g90_1 + 0.011456521073065164*g155_1) + (0.02937101220766003*g54_1 + 0.030019523538494547*g159_1 + -0.048653859365217586*g130_1 + 0.024595343316933086*g102_1 + -0.01139310023776304*g22_1 + -0.034274465690691154*g128_1 + -0.028464532383166666*g104_1 + -0.10392894538156829*g168_1 + 0.054610269734419584*g6_1 + 0.024766907819579076*g105_1 + 0.073559631438280634*g40_1 + -0.025933191268230203*g162_1 + -0.041581353504957397*g110_1 + 0.016996141960956401*g146_1 + 0.011334674092221839*g187_1 + 0.055952551768888428*g111_1 + -0.080148506859961041*g48_1); const v4d a2 = (-0.0031552969539661805*g4_2 + -0.0043324858141240048*g69_2 + -0.010114164984912428*g44_2 + 0.073510516252662653*g3_2 + 0.024595343316933086*g102_2 + 0.032427838460143167*g72_2 + 0.030750509103670831*g86_2 + -0.028464532383166666*g104_2 + 0.0048597201592666204*g171_2 + 0.0056502717674014749*g16_2 + -0.029668188742767505*g79_2 + -0.02254402260875036*g2_2 + 0.020985953019582296*g78_2 + 0.016088084791786708*g125_2 + 0.048319846544610169*g37_2 + -0.042126419629985361*g154_2 + 0.010877708433147427*g15_2 + -0.029562284220157588*g20_2 + 0.055952551768888428*g111_2 + -0.010255283712784159*g121_2 + 0.011456521073065164*g155_2 + -0.0043809361141887134*g74_2) + (-0.10247627259331378*g92_2 + 0.030019523538494547*g159_2 + -0.013441057650104648*g123_2 + 0.034063504113431793*g80_2 + -0.058480359020799254*g19_2 + -0.01139310023776304*g22_2 + -0.034274465690691154*g128_2 + 0.013148109026091256*g112_2 + -0.049804715123951307*g116_2 + -0.011144602794530492*g150_2 + 0.024766907819579076*g105_2 + -0.044629266165454026*g87_2 + -0.041581353504957397*g110_2 + -0.0091720819749502667*g126_2 + -0.043960390874211747*g165_2 + 0.011334674092221839*g187_2 + 0.0085572288999900097*g75_2 + -0.026889566032702698*g90_2 + -0.016384346970298995*g17_2 + 0.020906268826162363*g141_2 + -0.015826782810730279*g36_2);
    moment_arm[0 * kMaxElements + 96] = a0[0]; moment_arm[1 * kMaxElements + 96] = a0[1]; moment_arm[2 * kMaxElements + 96] = a0[2]; moment_arm[3 * kMaxElements + 96] = a1[0]; moment_arm[4 * kMaxElements + 96] = a1[1]; moment_arm[5 * kMaxElements + 96] = a1[2]; moment_arm[6 * kMaxElements + 96] = a2[0]; moment_arm[7 * kMaxElements + 96] = a2[1]; moment_arm[8 * kMaxElements + 96] = a2[2]; L[96] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.1817014990427957*e_len + 0.27500818618368489*g185_0 + -0.035991246017377833*g181_0 + -0.045153968405467683*g128_0 + -0.032332855001732545*g145_0 + -0.040832297458555662*g135_0 + -0.014724271660125413*g52_0 + 0.038602780075489791*g133_0) + (0.10751883711684322*g9_0 + 0.22878148650967942*g54_0 + -0.10249968121744521*g130_0 + -0.018807134471808307*g171_0 + -0.094606852386796489*g189_0 + 0.028563504964663096*g125_0 + 0.022250034980301411*g205_0 + -0.095344871995885566*g186_0); const v4d a1 = (0.062066739030243193*g114_1 + 0.22878148650967942*g54_1 + 0.11054955743350679*g6_1 + 0.099110476645386664*g113_1 + -0.10249968121744521*g130_1 + 0.1318516508809548*g109_1 + 0.004215607694238269*g86_1 + -0.032332855001732545*g145_1 + 0.041636742206358157*g80_1 + -0.037881715822809449*g104_1 + -0.094606852386796489*g189_1 + -0.030647415982493327*g87_1 + -0.016065307924111417*g120_1 + 0.038602780075489791*g133_1 + -0.095344871995885566*g186_1) + (0.27500818618368489*g185_1 + 0.070780666864263986*g116_1 + -0.035991246017377833*g181_1 + 0.059847485914990076*g22_1 + -0.045153968405467683*g128_1 + 0.010530276702032529*g102_1 + -0.026852535105229381*g90_1 + -0.16135951479639984*g31_1 + -0.014895092617833885*g77_1 + 0.011799223934014834*g105_1 + 0.005735632607425354*g89_1 + -0.054363575938670645*g96_1 + -0.040832297458555662*g135_1 + -0.029810120175939502*g108_1); const v4d a2 = (-0.03289577789944842*g20_2 + -0.003052978527544329*g69_2 + -0.0649795461456429*g19_2 + 0.059847485914990076*g22_2 + 0.010530276702032529*g102_2 + -0.018807134471808307*g171_2 + -0.026852535105229381*g90_2 + -0.031568126403745352*g16_2 + -0.014895092617833885*g77_2 + 0.011799223934014834*g105_2 + -0.030647415982493327*g87_2 + 0.0089165816503514565*g75_2 + -0.014724271660125413*g52_2 + -0.029810120175939502*g108_2 + 0.013723916743452781*g68_2) + (0.070780666864263986*g116_2 + 0.1684209259614991*g3_2 + -0.035991246017377833*g181_2 + -0.045153968405467683*g128_2 + 0.035825807244389538*g72_2 + 0.004215607694238269*g86_2 + -0.16135951479639984*g31_2 + 0.041636742206358157*g80_2 + -0.037881715822809449*g104_2 + 0.005735632607425354*g89_2 + -0.054363575938670645*g96_2 + 0.028563504964663096*g125_2 + 0.038602780075489791*g133_2 + -0.029939218259518195*g17_2 + 0.0076962534202833525*g73_2);
    moment_arm[0 * kMaxElements + 97] = a0[0]; moment_arm[1 * kMaxElements + 97] = a0[1]; moment_arm[2 * kMaxElements + 97] = a0[2]; moment_arm[3 * kMaxElements + 97] = a1[0]; moment_arm[4 * kMaxElements + 97] = a1[1]; moment_arm[5 * kMaxElements + 97] = a1[2]; moment_arm[6 * kMaxElements + 97] = a2[0]; moment_arm[7 * kMaxElements + 97] = a2[1]; moment_arm[8 * kMaxElements + 97] = a2[2]; L[97] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.15257040875099254*e_len + 0.10992297893428619*g9_0 + -0.014055988493542521*g142_0 + -0.089512300827182201*g174_0 + 0.0064790486420249985*g131_0 + -0.00043343255759417562*g132_0 + -0.034436647353992281*g173_0 + 0.0083705001037077953*g199_0 + 0.01777459324105387*g125_0 + -0.0056024879879413274*g124_0 + 0.029607789789942565*g136_0) + (0.0050207759946544351*g58_0 + -0.041457846637544017*g10_0 + -0.10364540981383667*g130_0 + -0.020692504632635424*g128_0 + -0.065188078449031281*g172_0 + -0.08351428491692639*g157_0 + 0.00030025172546867089*g135_0 + -0.057495746265321702*g145_0 + -0.012214754924332655*g38_0 + 0.042945786777869324*g40_0); const v4d a1 = (-0.055610320056415426*g34_1 + 0.069420878874780892*g109_1 + 0.026808939552005806*g102_1 + -0.10364540981383667*g130_1 + -0.041074473467859383*g106_1 + -0.089512300827182201*g174_1 + 0.032393691774574462*g80_1 + -0.020692504632635424*g128_1 + -0.0048724987851037852*g88_1 + 0.021122691892437123*g105_1 + -0.00043343255759417562*g132_1 + -0.034436647353992281*g173_1 + -0.057495746265321702*g145_1 + -0.036378086200528403*g87_1 + -0.014558098913227048*g25_1 + 0.023133810487226656*g112_1 + 0.097402373913207468*g113_1 + 0.10794507011667925*g119_1 + 0.029607789789942565*g136_1) + (-0.025355689692736192*g104_1 + 0.081333316608493009*g107_1 + -0.057608326019868997*g29_1 + -0.056714879117772385*g116_1 + 0.0073369998538940703*g100_1 + -0.066410804165348197*g118_1 + 0.0061066098961145461*g103_1 + 0.0064790486420249985*g131_1 + -0.026648222145408271*g108_1 + -0.065188078449031281*g172_1 + -0.08351428491692639*g157_1 + 0.00030025172546867089*g135_1 + 0.016522267558987013*g86_1 + 0.052886744431198798*g26_1 + -0.021901232094052467*g90_1 + -0.0056741417339963417*g101_1 + 0.011109631015569348*g21_1 + 0.042945786777869324*g40_1 + 0.0078747680160760111*g24_1); const v4d a2 = (-0.025355689692736192*g104_2 + -0.039442974564148373*g17_2 + 0.026808939552005806*g102_2 + -0.014055988493542521*g142_2 + -0.048799443115387302*g19_2 + -0.041074473467859383*g106_2 + 0.0073369998538940703*g100_2 + 0.0061066098961145461*g103_2 + 0.0064790486420249985*g131_2 + -0.026648222145408271*g108_2 + -0.0062544319261048685*g74_2 + 0.0082300897721680269*g75_2 + 0.0083705001037077953*g199_2 + 0.01777459324105387*g125_2 + -0.027632823177005848*g20_2 + -0.0056024879879413274*g124_2 + -0.036378086200528403*g87_2 + -0.014558098913227048*g25_2 + 0.023133810487226656*g112_2 + -0.018177338023593798*g71_2 + 0.016998277277929463*g18_2 + 0.029607789789942565*g136_2) + (-0.010006516663471051*g4_2 + 0.081333316608493009*g107_2 + -0.033702241338155733*g2_2 + 0.10421989094855261*g3_2 + -0.056714879117772385*g116_2 + 0.029226422742109133*g72_2 + 0.032393691774574462*g80_2 + -0.020692504632635424*g128_2 + -0.0048724987851037852*g88_2 + -0.0022747083695659944*g69_2 + 0.021122691892437123*g105_2 + -0.00043343255759417562*g132_2 + 0.016522267558987013*g86_2 + -0.012214754924332655*g38_2 + 0.0063105350020231897*g70_2 + 0.0014167721181326043*g68_2 + 0.052886744431198798*g26_2 + -0.021901232094052467*g90_2 + -0.0056741417339963417*g101_2 + 0.01633106636083179*g16_2 + 0.011109631015569348*g21_2);
    moment_arm[0 * kMaxElements + 98] = a0[0]; moment_arm[1 * kMaxElements + 98] = a0[1]; moment_arm[2 * kMaxElements + 98] = a0[2]; moment_arm[3 * kMaxElements + 98] = a1[0]; moment_arm[4 * kMaxElements + 98] = a1[1]; moment_arm[5 * kMaxElements + 98] = a1[2]; moment_arm[6 * kMaxElements + 98] = a2[0]; moment_arm[7 * kMaxElements + 98] = a2[1]; moment_arm[8 * kMaxElements + 98] = a2[2]; L[98] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.20468809291838896*e_len + 0.0014659986265918338*g188_0 + -0.11832418853376285*g47_0 + -0.031586742698672239*g202_0 + -0.008744169155455719*g213_0 + -0.091265182949006166*g157_0 + 0.010180660199163147*g48_0 + -0.017369168147181223*g10_0 + 0.053655933766371892*g162_0) + (-0.018333615488198899*g58_0 + 0.031720013641035688*g134_0 + 0.0038373508764683525*g59_0 + 0.0027730750155806109*g132_0 + -0.019833411557782916*g182_0 + 0.061230111930799101*g39_0 + -0.018329127069914793*g144_0 + 0.0097926160320228224*g37_0); const v4d a1 = (0.035496235404483684*g114_1 + 0.0014659986265918338*g188_1 + 0.069277279059951083*g6_1 + 0.031720013641035688*g134_1 + -0.035475084110190902*g82_1 + -0.011820905605222526*g79_1 + 0.0027730750155806109*g132_1 + 0.013791896136050592*g103_1 + -0.030828094872025136*g7_1 + 0.061230111930799101*g39_1 + 0.010180660199163147*g48_1 + 0.014453497781177537*g86_1 + -0.022186954835109275*g104_1 + -0.056601885884503204*g33_1 + -0.023111320083667477*g87_1 + 0.053655933766371892*g162_1) + (-0.030056773075032416*g84_1 + 0.014706132255087923*g102_1 + -0.065378307144745365*g31_1 + -0.11832418853376285*g47_1 + 0.091270489215172362*g109_1 + -0.031586742698672239*g202_1 + 0.012616395381256732*g100_1 + -0.019833411557782916*g182_1 + -0.091265182949006166*g157_1 + -0.01012558345077464*g77_1 + -0.018329127069914793*g144_1 + 0.013116248674626973*g78_1 + 0.016993652080669917*g105_1 + -0.010627506931574417*g110_1 + 0.022466420815435605*g26_1 + 0.0491281682476944*g98_1); const v4d a2 = (-0.0088490540629846907*g74_2 + 0.0014659986265918338*g188_2 + 0.094552427828261704*g3_2 + -0.016536741232464479*g20_2 + -0.026354952062517846*g2_2 + -0.00067113974633352922*g69_2 + 0.012616395381256732*g100_2 + -0.036900854411198052*g19_2 + -0.028424827990382283*g17_2 + -0.01012558345077464*g77_2 + 0.013116248674626973*g78_2 + 0.016993652080669917*g105_2 + 0.0073473494738784664*g73_2 + -0.010627506931574417*g110_2 + 0.0097926160320228224*g37_2) + (-0.014317407498190078*g4_2 + 0.014706132255087923*g102_2 + -0.065378307144745365*g31_2 + -0.035475084110190902*g82_2 + -0.011820905605222526*g79_2 + 0.0027730750155806109*g132_2 + 0.013791896136050592*g103_2 + 0.021989858786770074*g72_2 + 0.0073312423443974897*g75_2 + 0.014453497781177537*g86_2 + -0.022186954835109275*g104_2 + -0.013492872445443374*g71_2 + 0.011615490104454812*g16_2 + -0.023111320083667477*g87_2 + 0.022466420815435605*g26_2);
    moment_arm[0 * kMaxElements + 99] = a0[0]; moment_arm[1 * kMaxElements + 99] = a0[1]; moment_arm[2 * kMaxElements + 99] = a0[2]; moment_arm[3 * kMaxElements + 99] = a1[0]; moment_arm[4 * kMaxElements + 99] = a1[1]; moment_arm[5 * kMaxElements + 99] = a1[2]; moment_arm[6 * kMaxElements + 99] = a2[0]; moment_arm[7 * kMaxElements + 99] = a2[1]; moment_arm[8 * kMaxElements + 99] = a2[2]; L[99] = a0[3] + a1[3] + a2[3]; }
  { const v4d a0 = (0.20945053333719552*e_len + -0.00067257735173615848*g36_0 + -0.011432775310029276*g203_0 + 0.0031835000204333019*g178_0 + 0.0028594903260788541*g49_0 + 0.0035630789434814157*g159_0 + -0.0071393786464981823*g10_0) + (-0.002070245969097695*g52_0 + 0.0049301589994400537*g55_0 + -0.00019223802323854161*g130_0 + -0.018737919607442474*g134_0 + 0.0029236792232143101*g123_0 + -0.0074544809702712517*g140_0); const v4d a1 = (-0.0013033300426619852*g27_1 + -0.0019326157366814003*g116_1 + -0.021141905004770433*g108_1 + 0.031505056439392047*g111_1 + -0.040749377651207307*g31_1 + 0.0049301589994400537*g55_1 + -0.00019223802323854161*g130_1 + -0.031254452182523242*g106_1 + -0.015342294839027222*g5_1 + 0.0054210989206825173*g101_1 + -0.023320909603532197*g87_1 + -0.018737919607442474*g134_1 + 0.0035630789434814157*g159_1 + -0.0074544809702712517*g140_1 + 0.025668962058233012*g107_1) + (0.032722758967853482*g24_1 + -0.098822956932345773*g99_1 + -0.21382628453993294*g29_1 + -0.026509420646368284*g104_1 + 0.0080010234986500582*g80_1 + -0.011432775310029276*g203_1 + 0.11410192808202471*g114_1 + 0.015702259462705551*g78_1 + -0.048639783769442779*g7_1 + 0.00097935316171741059*g83_1 + -0.078721701143753223*g118_1 + 0.009570574331390384*g89_1 + -0.015814090879100729*g91_1 + 0.013761894300525561*g105_1 + 0.010011955526345514*g102_1); const v4d a2 = (-0.0013033300426619852*g27_2 + -0.016188743021858947*g4_2 + -0.021141905004770433*g108_2 + -0.026509420646368284*g104_2 + 0.0080010234986500582*g80_2 + 0.091441736303316409*g3_2 + -0.031254452182523242*g106_2 + -0.011602247430339298*g74_2 + 0.015702259462705551*g78_2 + 0.0031835000204333019*g178_2 + 0.0054210989206825173*g101_2 + -0.00052620373753267343*g69_2 + -0.029094614100943321*g17_2 + 0.0029236792232143101*g123_2 + -0.015814090879100729*g91_2 + 0.0048829120879741615*g15_2 + 0.013761894300525561*g105_2 + 0.010011955526345514*g102_2) + (-0.0019326157366814003*g116_2 + -0.002070245969097695*g52_2 + 0.031505056439392047*g111_2 + -0.040749377651207307*g31_2 + -0.00067257735173615848*g36_2 + -0.020549994436754992*g2_2 + 0.006001584126319022*g70_2 + 0.0069561200462386792*g75_2 + 0.022718087455701981*g72_2 + -0.033685750371342124*g19_2 + 0.00097935316171741059*g83_2 + -0.023320909603532197*g87_2 + 0.009570574331390384*g89_2 + 0.0035630789434814157*g159_2 + 0.0060806111355947217*g73_2 + -0.014985226861032222*g20_2 + 0.025668962058233012*g107_2);
    moment_arm[0 * kMaxElements + 100] = a0[0]; moment_arm[1 * kMaxElements + 100] = a0[1]; moment_arm[2 * kMaxElements + 100] = a0[2]; moment_arm[3 * kMaxElements + 100] = a1[0]; moment_arm[4 * kMaxElements + 100] = a1[1]; moment_arm[5 * kMaxElements + 100] = a1[2]; moment_arm[6 * kMaxElements + 100] = a2[0]; moment_arm[7 * kMaxElements + 100] = a2[1]; moment_arm[8 * kMaxElements + 100] = a2[2]; L[100] = a0[3] + a1[3] + a2[3]; }
  { const v4d a1 = (0.16796392198023305*e_len + -0.092504962068319027*g24_1 + -0.06753847966946229*g98_1 + -0.080237719440392097*g31_1 + 0.018867062233003485*g78_1 + 0.042312679137080776*g25_1 + -0.033617759354510543*g110_1 + -0.0081896347308790321*g90_1 + 0.064362180459651919*g99_1 + -0.0029419707383336467*g85_1 + -0.01613177387163826*g87_1 + -0.013272990903357037*g117_1 + -0.029432899986955294*g92_1 + 0.0086783101510858451*g115_1) + (-0.01312478848159134*g112_1 + -0.019755274088113339*g104_1 + 0.0048167584399074394*g116_1 + 0.018020381481759939*g105_1 + -0.029165011512037115*g108_1 + -0.067863201126786496*g5_1 + 0.033688339369455277*g27_1 + 0.022374610897066764*g91_1 + 0.13393540104621196*g109_1 + 0.030844306625454839*g114_1 + 0.051542455885392226*g6_1 + -0.013446712235568802*g88_1 + 0.0076833174191923434*g102_1 + -0.012422955626197435*g30_1); const v4d a2 = (-0.01312478848159134*g112_2 + 0.0048167584399074394*g116_2 + -0.080237719440392097*g31_2 + 0.018867062233003485*g78_2 + 0.0015449767528573429*g69_2 + 0.10407800142504517*g3_2 + 0.033688339369455277*g27_2 + 0.022374610897066764*g91_2 + 0.018234169738586135*g72_2 + -0.0029419707383336467*g85_2 + -0.013272990903357037*g117_2 + -0.031745328173974088*g17_2 + 0.0076833174191923434*g102_2 + 0.0056152636101077904*g67_2 + -0.012422955626197435*g30_2) + (-0.019755274088113339*g104_2 + -0.017394680709037668*g20_2 + 0.018020381481759939*g105_2 + -0.029165011512037115*g108_2 + 0.042312679137080776*g25_2 + -0.033617759354510543*g110_2 + -0.0081896347308790321*g90_2 + -0.038366725871125267*g19_2 + -0.015189056891249808*g74_2 + -0.01613177387163826*g87_2 + -0.013446712235568802*g88_2 + -0.029432899986955294*g92_2 + 0.004573634960326204*g75_2 + 0.0086783101510858451*g115_2);
    moment_arm[3 * kMaxElements + 101] = a1[0]; moment_arm[4 * kMaxElements + 101] = a1[1]; moment_arm[5 * kMaxElements + 101] = a1[2]; moment_arm[6 * kMaxElements + 101] = a2[0]; moment_arm[7 * kMaxElements + 101] = a2[1]; moment_arm[8 * kMaxElements + 101] = a2[2]; L[101] = a1[3] + a2[3]; }
  { const v4d a1 = (0.16267042119067254*e_len + -0.00087317527947859339*g97_1 + 0.029170937957529536*g6_1 + -0.012949546113279545*g87_1 + -0.009500081765234529*g83_1 + -0.063224789649791863*g7_1 + 0.033974460980875656*g118_1 + -0.051094987858721269*g31_1 + -0.019734749244870429*g106_1 + -0.06963306103823319*g29_1 + -0.095085515244391419*g33_1 + 0.0081592738957368335*g101_1 + 0.021831365699659662*g25_1) + (0.019325749765121795*g24_1 + -0.015225336847922794*g104_1 + 0.0045277905962480972*g102_1 + -0.036189268946097357*g108_1 + -0.00065545788478841194*g92_1 + 0.017297810841904192*g78_1 + 0.0076293048170642322*g105_1 + 0.020652024333137696*g95_1 + 0.0072038857509275234*g103_1 + -0.0051386829301502904*g96_1 + 0.073695076889894684*g114_1 + 0.010388147891782202*g89_1 + 0.029010719728724432*g35_1); const v4d a2 = (-0.00087317527947859339*g97_2 + 0.0045277905962480972*g102_2 + -0.012949546113279545*g87_2 + 0.063961949750392919*g3_2 + -0.00065545788478841194*g92_2 + -0.0097122003767623477*g74_2 + -0.051094987858721269*g31_2 + 0.0031357990343844591*g67_2 + -0.019734749244870429*g106_2 + 0.011243179321435291*g72_2 + -0.018757520570691806*g19_2 + 0.0081592738957368335*g101_2 + 0.010388147891782202*g89_2 + 0.021831365699659662*g25_2 + -0.0064317765033350405*g20_2) + (-0.015225336847922794*g104_2 + -0.019436600863325052*g4_2 + -0.036189268946097357*g108_2 + -0.009500081765234529*g83_2 + 0.017297810841904192*g78_2 + 0.0076293048170642322*g105_2 + 0.020652024333137696*g95_2 + -0.011509191615600184*g2_2 + 0.0072038857509275234*g103_2 + -0.019032227228392692*g17_2 + -0.0051386829301502904*g96_2 + 0.0046682409444260562*g75_2 + 0.0011417206940884442*g66_2 + 0.0069433204688588036*g70_2);
    moment_arm[3 * kMaxElements + 102] = a1[0]; moment_arm[4 * kMaxElements + 102] = a1[1]; moment_arm[5 * kMaxElements + 102] = a1[2]; moment_arm[6 * kMaxElements + 102] = a2[0]; moment_arm[7 * kMaxElements + 102] = a2[1]; moment_arm[8 * kMaxElements + 102] = a2[2]; L[102] = a1[3] + a2[3]; }
  { const v4d a3 = (0.15248608316782825*e_len) + (0.019723567450666096*g1_3);
    moment_arm[9 * kMaxElements + 103] = a3[0]; moment_arm[10 * kMaxElements + 103] = a3[1]; L[103] = a3[3]; }
  { const v4d a3 = (0.17613639181439189*e_len + -0.00043991721739145294*g13_3) + (0.020354325822973557*g1_3);
    moment_arm[9 * kMaxElements + 104] = a3[0]; moment_arm[10 * kMaxElements + 104] = a3[1]; L[104] = a3[3]; }
  { const v4d a3 = (0.061683638028087691*e_len) + (0.018447092260682727*g1_3);
    moment_arm[9 * kMaxElements + 105] = a3[0]; moment_arm[10 * kMaxElements + 105] = a3[1]; L[105] = a3[3]; }
  { const v4d a3 = (0.10016830893357324*e_len + -0.0024874901285840863*g13_3) + (0.021270428198918022*g1_3 + 0.00058036928078897504*g63_3);
    moment_arm[9 * kMaxElements + 106] = a3[0]; moment_arm[10 * kMaxElements + 106] = a3[1]; L[106] = a3[3]; }
  { const v4d a3 = (0.14342323450261224*e_len + -0.0023577974300801412*g13_3) + (0.02121815221991654*g1_3 + 0.00055104580499355359*g63_3);
    moment_arm[9 * kMaxElements + 107] = a3[0]; moment_arm[10 * kMaxElements + 107] = a3[1]; L[107] = a3[3]; }
  { const v4d a3 = (0.18916082621667812*e_len + -0.010341557171103547*g13_3) + (-0.012075685340610197*g1_3 + 5.952982163514211e-05*g271_3);
    moment_arm[9 * kMaxElements + 108] = a3[0]; moment_arm[10 * kMaxElements + 108] = a3[1]; L[108] = a3[3]; }
  { const v4d a3 = (0.1805481467819168*e_len + -0.0096453236384304725*g13_3) + (-0.012346590404526897*g1_3 + 5.9263831561071173e-05*g271_3);
    moment_arm[9 * kMaxElements + 109] = a3[0]; moment_arm[10 * kMaxElements + 109] = a3[1]; L[109] = a3[3]; }
  { const v4d a3 = (0.14528402172990038*e_len + 0.0041156866190291434*g13_3 + 0.00059308492869950338*g243_3) + (-0.015504427162474892*g1_3 + -2.1624658717477171e-06*g309_3 + -0.0060724210605351461*g63_3);
    moment_arm[9 * kMaxElements + 110] = a3[0]; moment_arm[10 * kMaxElements + 110] = a3[1]; L[110] = a3[3]; }
  { const v4d a3 = (0.14328771737412008*e_len + -0.0097140182743692214*g13_3) + (-0.010902805651531499*g1_3 + 7.4015065198838516e-06*g307_3);
    moment_arm[9 * kMaxElements + 111] = a3[0]; moment_arm[10 * kMaxElements + 111] = a3[1]; L[111] = a3[3]; }
  { const v4d a3 = (0.1107178969046228*e_len + -0.014548795826460842*g1_3 + -0.0022344501399263572*g63_3) + (-0.00060721045724996723*g13_3 + 2.1422059417280247e-06*g309_3);
    moment_arm[9 * kMaxElements + 112] = a3[0]; moment_arm[10 * kMaxElements + 112] = a3[1]; L[112] = a3[3]; }
  { const v4d a3 = (0.098126182109802632*e_len + -0.0010565669989135178*g13_3 + -0.0015507804132241666*g63_3) + (-0.014253654440665123*g1_3 + 2.0690407301920543e-06*g309_3);
    moment_arm[9 * kMaxElements + 113] = a3[0]; moment_arm[10 * kMaxElements + 113] = a3[1]; L[113] = a3[3]; }
  { const v4d a3 = (0.096622107341881161*e_len + -0.01436884991508092*g1_3 + -0.0021029674116264966*g63_3) + (-0.0013017240422664822*g13_3 + 1.841615491766844e-06*g309_3);
    moment_arm[9 * kMaxElements + 114] = a3[0]; moment_arm[10 * kMaxElements + 114] = a3[1]; L[114] = a3[3]; }
  { const v4d a3 = (0.33978457477225743*e_len + -0.029125175610834369*g13_3 + 0.006214126539918945*g11_3 + -0.0029775943421227282*g60_3 + -2.1557843512702104e-05*g303_3) + (-0.017371547041246761*g1_3 + 0.00058107274604836303*g243_3 + 0.00011491911517209033*g239_3 + -0.00039803270462548159*g240_3 + 0.0015749078040528453*g216_3);
    moment_arm[9 * kMaxElements + 115] = a3[0]; moment_arm[10 * kMaxElements + 115] = a3[1]; L[115] = a3[3]; }
  { const v4d a3 = (0.32523986160151908*e_len + -0.024239567688537182*g13_3 + 0.0041493196616565909*g11_3 + -0.0008629037985071862*g240_3 + -0.0024070209268110903*g60_3 + -0.00027037771472469471*g242_3) + (-0.011011329858490817*g1_3 + 0.00045970352795520148*g243_3 + 0.00013270767037049401*g239_3 + 2.7134233239903423e-05*g302_3 + 0.0026327441230012839*g216_3);
    moment_arm[9 * kMaxElements + 116] = a3[0]; moment_arm[10 * kMaxElements + 116] = a3[1]; L[116] = a3[3]; }
  { const v4d a3 = (0.30997411835046162*e_len + 0.0014696024618042814*g219_3 + -1.5110615668157653e-05*g304_3) + (-0.024625387225861356*g13_3 + 0.0027771391139016287*g12_3 + -0.0032910210616908663*g1_3);
    moment_arm[9 * kMaxElements + 117] = a3[0]; moment_arm[10 * kMaxElements + 117] = a3[1]; L[117] = a3[3]; }
  { const v4d a3 = (0.16411749763322456*e_len + 0.00017008454930036865*g215_3 + 3.3407850817808397e-06*g304_3 + 0.005674798877102369*g0_3 + -0.00074991982754013054*g1_3 + -2.234723965398114e-05*g269_3 + -0.00012266338908027119*g267_3) + (-0.0019651154480968113*g12_3 + -0.0062360332454371335*g13_3 + 3.5248530677121392e-05*g301_3 + 0.0013232700009288994*g63_3 + -0.002590927243780817*g11_3 + 0.00069809326606655496*g62_3 + 1.1632983457792069e-05*g268_3);
    moment_arm[9 * kMaxElements + 118] = a3[0]; moment_arm[10 * kMaxElements + 118] = a3[1]; L[118] = a3[3]; }
  { const v4d a3 = (0.090283356645272969*e_len + 2.2209198593068478e-07*g308_3) + (-0.00073138878566437571*g60_3 + 0.0019028484496048776*g0_3);
    moment_arm[9 * kMaxElements + 119] = a3[0]; moment_arm[10 * kMaxElements + 119] = a3[1]; L[119] = a3[3]; }
  { const v4d a3 = (0.017955686666121778*e_len + 2.2154159451120803e-05*g267_3 + 0.005063677853274229*g11_3) + (0.015131385021440734*g0_3 + -3.0069698027888411e-07*g308_3 + -0.001979822239013091*g60_3);
    moment_arm[9 * kMaxElements + 120] = a3[0]; moment_arm[10 * kMaxElements + 120] = a3[1]; L[120] = a3[3]; }
  { const v4d a3 = (0.020274138158276955*e_len + 7.3967630650754768e-06*g301_3 + 0.0043603490105709299*g11_3) + (0.012157600516321728*g0_3 + -4.8416579022964509e-07*g308_3 + -0.0015510705674651566*g60_3);
    moment_arm[9 * kMaxElements + 121] = a3[0]; moment_arm[10 * kMaxElements + 121] = a3[1]; L[121] = a3[3]; }
  { const v4d a3 = (0.025521087637750527*e_len + 1.3931520949913255e-07*g308_3 + -0.0012904105736931018*g60_3) + (0.0064650457388534498*g0_3 + 0.004907745671472976*g11_3);
    moment_arm[9 * kMaxElements + 122] = a3[0]; moment_arm[10 * kMaxElements + 122] = a3[1]; L[122] = a3[3]; }
  { const v4d a3 = (0.027341017052873*e_len + 2.9063854697313307e-06*g306_3 + -0.01136548536343018*g60_3 + -0.00079595888595676014*g239_3) + (0.0030672939531378226*g0_3 + 0.01392242270251493*g11_3 + 0.0046347939691149549*g215_3);
    moment_arm[9 * kMaxElements + 123] = a3[0]; moment_arm[10 * kMaxElements + 123] = a3[1]; L[123] = a3[3]; }
  { const v4d a3 = (0.029979053642745678*e_len + -4.1320641815285589e-06*g267_3) + (0.0098604213493196126*g0_3);
    moment_arm[9 * kMaxElements + 124] = a3[0]; moment_arm[10 * kMaxElements + 124] = a3[1]; L[124] = a3[3]; }
  { const v4d a3 = (0.055159413124025017*e_len + -0.0019618048731345388*g0_3) + (-0.0013644654229857511*g11_3);
    moment_arm[9 * kMaxElements + 125] = a3[0]; moment_arm[10 * kMaxElements + 125] = a3[1]; L[125] = a3[3]; }
  { const v4d a3 = (0.052339406354759054*e_len + -0.0037676250766220708*g0_3) + (-0.0014025331906435234*g11_3);
    moment_arm[9 * kMaxElements + 126] = a3[0]; moment_arm[10 * kMaxElements + 126] = a3[1]; L[126] = a3[3]; }
  { const v4d a3 = (0.050566575161723741*e_len + -0.001369308478210926*g11_3) + (-0.0048262625892505845*g0_3);
    moment_arm[9 * kMaxElements + 127] = a3[0]; moment_arm[10 * kMaxElements + 127] = a3[1]; L[127] = a3[3]; }
  { const v4d a3 = (0.2288811253778478*e_len + -0.00071616131486152844*g13_3) + (0.02145331003745176*g1_3);
    moment_arm[9 * kMaxElements + 128] = a3[0]; moment_arm[10 * kMaxElements + 128] = a3[1]; L[128] = a3[3]; }
  { const v4d a3 = (0.23150687177995355*e_len + -0.00070869324314726549*g13_3) + (0.021390967597154122*g1_3);
    moment_arm[9 * kMaxElements + 129] = a3[0]; moment_arm[10 * kMaxElements + 129] = a3[1]; L[129] = a3[3]; }
  { const v4d a3 = (0.23617457282841625*e_len) + (0.019444970517437255*g1_3);
    moment_arm[9 * kMaxElements + 130] = a3[0]; moment_arm[10 * kMaxElements + 130] = a3[1]; L[130] = a3[3]; }
  { const v4d a3 = (0.1964255398955991*e_len) + (0.019379502606780251*g1_3);
    moment_arm[9 * kMaxElements + 131] = a3[0]; moment_arm[10 * kMaxElements + 131] = a3[1]; L[131] = a3[3]; }
  { const v4d a3 = (0.19250762937750199*e_len) + (0.0189781619414458*g1_3);
    moment_arm[9 * kMaxElements + 132] = a3[0]; moment_arm[10 * kMaxElements + 132] = a3[1]; L[132] = a3[3]; }
  { const v4d a3 = (0.01937716682349119*e_len + -0.00054640570364993511*g63_3) + (0.0082495373717470198*g1_3);
    moment_arm[9 * kMaxElements + 133] = a3[0]; moment_arm[10 * kMaxElements + 133] = a3[1]; L[133] = a3[3]; }
  { const v4d a3 = (0.019017026128664308*e_len + -3.5587617786331501e-05*g243_3) + (0.0072493784155107793*g1_3);
    moment_arm[9 * kMaxElements + 134] = a3[0]; moment_arm[10 * kMaxElements + 134] = a3[1]; L[134] = a3[3]; }
  { const v4d a3 = (0.021621350307338864*e_len + 0.010453580477736302*g1_3) + (-1.4667805877390998e-07*g309_3 + -0.0027698854892570881*g13_3);
    moment_arm[9 * kMaxElements + 135] = a3[0]; moment_arm[10 * kMaxElements + 135] = a3[1]; L[135] = a3[3]; }
  { const v4d a3 = (0.049690548133627478*e_len + -6.211942732309942e-07*g309_3) + (0.002198639824461294*g1_3 + 0.001371314856838501*g13_3);
    moment_arm[9 * kMaxElements + 136] = a3[0]; moment_arm[10 * kMaxElements + 136] = a3[1]; L[136] = a3[3]; }
  { const v4d a3 = (0.033729546777096546*e_len + 1.6817473074144646e-07*g309_3 + -0.001354639752399062*g63_3) + (0.00266945539927878*g1_3 + 0.0045890735552252624*g13_3);
    moment_arm[9 * kMaxElements + 137] = a3[0]; moment_arm[10 * kMaxElements + 137] = a3[1]; L[137] = a3[3]; }
}

void gh_directions(const double* q, double* d) {
  const double q0 = q[0];
  const double q0_2 = q0*q0;
  const double q1 = q[1];
  const double q1_2 = q1*q1;
  const double q2 = q[2];
  const double q3 = q[3];
  const double q3_2 = q3*q3;
  const double q4 = q[4];
  const double q4_2 = q4*q4;
  const double q5 = q[5];
  const double q5_2 = q5*q5;
  const double q6 = q[6];
  const double q6_2 = q6*q6;
  const double q6_3 = q6_2*q6;
  const double q7 = q[7];
  const double q7_2 = q7*q7;
  const double q7_3 = q7_2*q7;
  const double q8 = q[8];
  const double q8_2 = q8*q8;
  const double q8_3 = q8_2*q8;
  const double q9 = q[9];
  const double q9_2 = q9*q9;
  const double q9_3 = q9_2*q9;
  const double m0 = q7;
  const double m1 = q6*q7_2;
  const double m2 = q6*q7;
  const double m3 = q7_3;
  const double m4 = q8;
  const double m5 = q6_2*q7;
  const double m6 = q6*q8_2;
  const double m7 = q7_2;
  const double m8 = q6;
  const double m9 = q6_3;
  const double m10 = q6_2;
  const double m11 = q7_2*q8;
  const double m12 = q7*q8;
  const double m13 = q3*q7;
  const double m14 = q3*q6*q7;
  const double m15 = q3*q7_2;
  const double m16 = q3_2*q7;
  const double m17 = q3_2*q8;
  const double m18 = q6*q8;
  const double m19 = q4*q7*q8;
  const double m20 = q5*q6_2;
  const double m21 = q6*q7*q8;
  const double m22 = q6_2*q8;
  const double m23 = q7*q8_2;
  const double m24 = q8_2;
  const double m25 = q8_3;
  const double m26 = q9_3;
  const double m27 = q1*q3_2;
  const double m28 = q3_2*q5;
  const double m29 = q4;
  const double m30 = q0*q6*q7;
  const double m31 = q3;
  const double m32 = q1*q5;
  const double m33 = q0_2*q4;
  const double m34 = q0*q4;
  const double m35 = q1*q4;
  const double m36 = q1*q3;
  const double m37 = q0*q3*q6;
  const double m38 = q4*q5*q7;
  const double m39 = q0*q2*q6;
  const double m40 = q3*q5*q7;
  const double m41 = q1_2*q7;
  const double m42 = q2*q6;
  const double m43 = q5*q7;
  const double m44 = q3*q4*q6;
  const double m45 = q4*q6*q7;
  const double m46 = q4_2*q6;
  const double m47 = q4*q6*q8;
  const double m48 = q5_2*q8;
  const double m49 = q5*q6*q8;
  const double m50 = q3_2*q6;
  const double m51 = q3*q5*q8;
  using v3d = double __attribute__((vector_size(32)));  // x, y, z and an unused lane
  double gx[138], gy[138], gz[138];
  gx[0] = 0.0; gy[0] = 0.0; gz[0] = 0.0;
  gx[1] = 0.0; gy[1] = 0.0; gz[1] = 0.0;
  gx[2] = 0.0; gy[2] = 0.0; gz[2] = 0.0;
  gx[3] = 0.0; gy[3] = 0.0; gz[3] = 0.0;
  gx[4] = 0.0; gy[4] = 0.0; gz[4] = 0.0;
  gx[5] = 0.0; gy[5] = 0.0; gz[5] = 0.0;
  gx[6] = 0.0; gy[6] = 0.0; gz[6] = 0.0;
  gx[7] = 0.0; gy[7] = 0.0; gz[7] = 0.0;
  gx[8] = 0.0; gy[8] = 0.0; gz[8] = 0.0;
  gx[9] = 0.0; gy[9] = 0.0; gz[9] = 0.0;
  gx[10] = 0.0; gy[10] = 0.0; gz[10] = 0.0;
  gx[11] = 0.0; gy[11] = 0.0; gz[11] = 0.0;
  gx[12] = 0.0; gy[12] = 0.0; gz[12] = 0.0;
  gx[13] = 0.0; gy[13] = 0.0; gz[13] = 0.0;
  gx[14] = 0.0; gy[14] = 0.0; gz[14] = 0.0;
  gx[15] = 0.0; gy[15] = 0.0; gz[15] = 0.0;
  gx[16] = 0.0; gy[16] = 0.0; gz[16] = 0.0;
  gx[17] = 0.0; gy[17] = 0.0; gz[17] = 0.0;
  gx[18] = 0.0; gy[18] = 0.0; gz[18] = 0.0;
  gx[19] = 0.0; gy[19] = 0.0; gz[19] = 0.0;
  gx[20] = 0.0; gy[20] = 0.0; gz[20] = 0.0;
  gx[21] = 0.0; gy[21] = 0.0; gz[21] = 0.0;
  gx[22] = 0.0; gy[22] = 0.0; gz[22] = 0.0;
  gx[23] = 0.0; gy[23] = 0.0; gz[23] = 0.0;
  gx[24] = 0.0; gy[24] = 0.0; gz[24] = 0.0;
  gx[25] = 0.0; gy[25] = 0.0; gz[25] = 0.0;
  gx[26] = 0.0; gy[26] = 0.0; gz[26] = 0.0;
  gx[27] = 0.0; gy[27] = 0.0; gz[27] = 0.0;
  gx[28] = 0.0; gy[28] = 0.0; gz[28] = 0.0;
  gx[29] = 0.0; gy[29] = 0.0; gz[29] = 0.0;
  gx[30] = 0.0; gy[30] = 0.0; gz[30] = 0.0;
  gx[31] = 0.0; gy[31] = 0.0; gz[31] = 0.0;
  gx[32] = 0.0; gy[32] = 0.0; gz[32] = 0.0;
  gx[33] = 0.0; gy[33] = 0.0; gz[33] = 0.0;
  gx[34] = 0.0; gy[34] = 0.0; gz[34] = 0.0;
  gx[35] = 0.0; gy[35] = 0.0; gz[35] = 0.0;
  { const v3d g = v3d{-0.61272317383468189, 0.7478855741851832, 0.25823103227244559, 0.0} + v3d{-0.3929023942778887, -0.29759148337663383, -0.16420709447038781, 0.0}*m0 + v3d{-0.087593236349634618, -0.050320311195787344, -0.21867020672380624, 0.0}*m1 + v3d{0.34412552575497746, 0.049343889112046589, 0.72152970545408945, 0.0}*m2 + v3d{0.053921384764924037, -0.079090641846211909, 0.035047281841937374, 0.0}*m3 + v3d{0.027257812902158222, -0.023872207469626192, 0.072655828734519576, 0.0}*m4; gx[36] = g[0]; gy[36] = g[1]; gz[36] = g[2]; }
  { const v3d g = v3d{-0.53862015553398945, 0.62480208339074794, 0.39848623069921052, 0.0} + v3d{0.16591850433688937, 0.32567575617464639, 0.085070151303133071, 0.0}*m3 + v3d{0.5453350953767091, 0.16762337773271399, 0.46091110364420329, 0.0}*m5 + v3d{-0.17966389274439643, 0.59739352939755463, -0.16062912891558567, 0.0}*m0 + v3d{-0.20145662985464255, -0.2129908737656514, -0.037147648407273373, 0.0}*m1 + v3d{0.21050070572328586, 0.038736415647767863, 0.22266293315672911, 0.0}*m6 + v3d{-0.29813930345201262, -1.0992071525895797, -0.050129182633238963, 0.0}*m7; gx[37] = g[0]; gy[37] = g[1]; gz[37] = g[2]; }
  { const v3d g = v3d{-0.42117416110262501, 0.65148128803861027, 0.38798557605312251, 0.0} + v3d{0.31573478842097541, 0.48004669864286525, -0.22629877965415973, 0.0}*m3 + v3d{0.53709450491808586, 0.05000356142846131, 0.3790510096682993, 0.0}*m1 + v3d{-0.71039951731962991, -1.4768176846982046, 0.55629348265639911, 0.0}*m7 + v3d{0.34426399561013471, 0.18555379464064786, 0.27191442140894395, 0.0}*m8 + v3d{0.02295541550833578, 0.84763137658205112, -0.3747847359030374, 0.0}*m0 + v3d{-0.76216772297040292, -0.3374343271520388, -0.26303002838367234, 0.0}*m2 + v3d{0.031408554210456845, -0.011233358243567439, -0.12983469630284597, 0.0}*m9; gx[38] = g[0]; gy[38] = g[1]; gz[38] = g[2]; }
  { const v3d g = v3d{-0.12331379014230116, 0.93820851155782969, 0.40227871203539628, 0.0} + v3d{0.13964959137445845, -0.10769148721793922, 0.031851086321287012, 0.0}*m3 + v3d{-0.11487781924754058, -0.16555987175807999, 0.19798715500796327, 0.0}*m8 + v3d{-0.84072987528690324, -0.3342041461189445, -0.089931180990684104, 0.0}*m0 + v3d{0.42107657184238373, 0.1033428751777469, 0.43742865084156396, 0.0}*m2 + v3d{0.20016781299183434, 0.23544194124622506, -0.18466264492422704, 0.0}*m10 + v3d{0.046748327420773075, -0.018242052793761284, 0.067051249111833008, 0.0}*m11 + v3d{-0.29214263022986164, -0.27754001123671274, -0.16264176368063551, 0.0}*m5; gx[39] = g[0]; gy[39] = g[1]; gz[39] = g[2]; }
  { const v3d g = v3d{-0.091806656327822478, 1.0101436810075159, 0.16480401643276224, 0.0} + v3d{0.085837195878258638, -0.24015819301978347, -0.16059602313200366, 0.0}*m7 + v3d{-0.062140283206924239, -0.28046795918485196, 0.44086451273990923, 0.0}*m2 + v3d{-0.71899983264293976, -0.18034166960683568, 0.37561339850338071, 0.0}*m0 + v3d{0.091190949563233412, 0.0026837547369796184, 0.098737241508722429, 0.0}*m12 + v3d{0.34882908040019101, 0.1431723174858735, -0.017659011606583234, 0.0}*m1; gx[40] = g[0]; gy[40] = g[1]; gz[40] = g[2]; }
  { const v3d g = v3d{-0.057063784424008543, 0.96730330088152361, 0.29410516731397718, 0.0} + v3d{0.29511347477450484, -0.22049738851445075, -0.011339165886477277, 0.0}*m7 + v3d{0.33192292009693963, -0.080233101558107922, 0.45190680998006688, 0.0}*m2 + v3d{-1.0367680187379726, -0.18323128658869201, 0.022165534802294846, 0.0}*m0 + v3d{0.045893420370272664, -0.026040121232143571, 0.086938541138425071, 0.0}*m4; gx[41] = g[0]; gy[41] = g[1]; gz[41] = g[2]; }
  { const v3d g = v3d{-0.0040259681404570848, 0.9735321768322206, 0.25992037755935554, 0.0} + v3d{-1.1148124224933682, -0.13726484310492892, 0.032837466123053244, 0.0}*m0 + v3d{0.37013246565593466, -0.071593062076962144, 0.51328756146872523, 0.0}*m2 + v3d{0.30139885262316313, -0.27328081666094423, -0.032974813244580153, 0.0}*m7 + v3d{0.044383858567773882, -0.015963030519943581, 0.077667037381492915, 0.0}*m4; gx[42] = g[0]; gy[42] = g[1]; gz[42] = g[2]; }
  { const v3d g = v3d{-0.10613913138629091, 1.0482973270732137, 0.11531225924473601, 0.0} + v3d{-0.68622466513035063, -0.28884763512393719, 0.1413793241025984, 0.0}*m0 + v3d{0.1587138350193297, -0.23505299754923611, 0.71647365661283358, 0.0}*m2 + v3d{0.18931113214693696, 0.13305003707992194, -0.15525288020357875, 0.0}*m1 + v3d{0.029116215942544047, -0.12468819944040554, -0.03221471780640868, 0.0}*m3 + v3d{0.048083548509060881, -0.02785469930381165, 0.10214129881744514, 0.0}*m4; gx[43] = g[0]; gy[43] = g[1]; gz[43] = g[2]; }
  { const v3d g = v3d{-0.062010857022767076, 1.0331589154961451, 0.034228103490863679, 0.0} + v3d{-0.847983354060731, -0.20172523665299683, 0.49324438270691678, 0.0}*m0 + v3d{0.57428838715926034, -0.017789016162369831, 0.52087480147065912, 0.0}*m2 + v3d{-0.18224229751645871, -0.063328031881299193, 0.0053587549313416699, 0.0}*m8 + v3d{0.091129885518796097, 0.042504104216471925, 0.070216234155291726, 0.0}*m12 + v3d{0.13324687476968203, -0.23576446510017801, -0.24798471308480838, 0.0}*m7; gx[44] = g[0]; gy[44] = g[1]; gz[44] = g[2]; }
  { const v3d g = v3d{-0.41603737552383757, 0.89361787850411123, 0.016763942612174048, 0.0} + v3d{-0.10371494317578972, 0.1759048405618126, 0.26858294612526357, 0.0}*m0 + v3d{0.18211081254503875, -0.31751397212524207, 0.93193529347014514, 0.0}*m2 + v3d{-0.22723497988007041, -0.42774901936143678, -0.080886436333653597, 0.0}*m7 + v3d{0.21200128755673042, 0.20776937033054607, -0.306262075817617, 0.0}*m1 + v3d{0.10572103759785741, 0.048495603551311994, 0.077494263704484659, 0.0}*m4; gx[45] = g[0]; gy[45] = g[1]; gz[45] = g[2]; }
  { const v3d g = v3d{-0.59305363553721224, 0.84424121433481025, 0.1321140180578512, 0.0} + v3d{0.26160254200382893, -0.047344434037089711, 0.37542102922070303, 0.0}*m8 + v3d{-0.15501844949274068, -0.17970474322855853, -0.0038168533594227249, 0.0}*m3 + v3d{0.18636722127595853, 0.0039801494396365968, 0.2310927188796309, 0.0}*m1 + v3d{0.126692131898067, 0.081275462343280078, 0.088966494266070131, 0.0}*m12; gx[46] = g[0]; gy[46] = g[1]; gz[46] = g[2]; }
  { const v3d g = v3d{-0.15292276627180124, 1.0111260250317402, 0.22863104960535044, 0.0} + v3d{-2.2769513044045113, -1.794480840120233, 0.70423463036905931, 0.0}*m13 + v3d{0.37812990945758607, 0.14953647285119981, 0.77808208050342076, 0.0}*m14 + v3d{0.41372639000964101, 0.015500377282088558, -0.18964863888381714, 0.0}*m15 + v3d{1.1623763007998522, 1.4939913309433233, -0.96063663263652765, 0.0}*m16 + v3d{0.20238425696595641, 0.16962552817790508, 0.095742046615340706, 0.0}*m17 + v3d{0.0090290075933374334, 0.013903736104010521, -0.13672103992283949, 0.0}*m10; gx[47] = g[0]; gy[47] = g[1]; gz[47] = g[2]; }
  { const v3d g = v3d{-0.3876393362026529, 0.96576256135520411, -0.062990220037423411, 0.0} + v3d{-0.55875667248960625, -0.42791683811168374, 0.32953578287660151, 0.0}*m0 + v3d{0.18715728855616975, 0.55218058099911016, 0.30942863391363062, 0.0}*m14 + v3d{0.13436325521920989, -0.046953791768683771, -0.30941332670522526, 0.0}*m15 + v3d{0.17279367032457171, 0.04636490149690823, 0.02698334320986738, 0.0}*m10 + v3d{0.15208689610079945, 0.15876911497758844, 0.055288379771504262, 0.0}*m17 + v3d{-0.01128522294845068, -0.21567055835411636, 0.11591487575375649, 0.0}*m1 + v3d{-0.073996963636638741, -0.090069551734354297, 0.062533642819072074, 0.0}*m8; gx[48] = g[0]; gy[48] = g[1]; gz[48] = g[2]; }
  { const v3d g = v3d{-0.34982901054365506, 0.95052741177174205, -0.0021744529998746023, 0.0} + v3d{0.33937958448405237, 0.43429985273883526, -0.3891522922518475, 0.0}*m13 + v3d{-0.067601075653142634, 0.090968754605887187, 0.53143097716811405, 0.0}*m14 + v3d{-0.80979320455287629, -0.58947860553728704, 0.45776083032243253, 0.0}*m0 + v3d{0.097369064061648566, -0.13096674334804739, -0.15379636445247188, 0.0}*m7 + v3d{0.12263223208410093, 0.042164440306672678, -0.027793185883043966, 0.0}*m18 + v3d{0.2250268413217085, 0.022256964536987462, 0.061897726903598321, 0.0}*m5 + v3d{-0.049834446364479548, -0.17596511594182435, -0.16893946680841793, 0.0}*m19; gx[49] = g[0]; gy[49] = g[1]; gz[49] = g[2]; }
  { const v3d g = v3d{-0.37825774515777705, 0.91815361841145116, -0.064667226706024136, 0.0} + v3d{0.11432836504827919, 0.32448206450708833, -0.46391368678790007, 0.0}*m13 + v3d{0.17699616167222504, 0.07478444560845271, 0.63444449493882693, 0.0}*m14 + v3d{-0.67701399597290579, -0.4316986877794583, 0.56754840121841321, 0.0}*m0 + v3d{-0.33969280352181724, -0.12308676395834185, -0.097064512522444246, 0.0}*m20 + v3d{0.10953702353486354, -0.18614609015879616, -0.16100016708468678, 0.0}*m7 + v3d{0.069847089758810169, 0.068771308114106755, 0.026304115541150971, 0.0}*m4; gx[50] = g[0]; gy[50] = g[1]; gz[50] = g[2]; }
  { const v3d g = v3d{-0.075094168380187426, 1.1612742357349186, -0.15477647070136705, 0.0} + v3d{-0.71791859279931669, -0.60795442697516, 0.0025273513370796929, 0.0}*m0 + v3d{0.26237925266341222, 0.089534991758664154, 0.65510250318863361, 0.0}*m2; gx[51] = g[0]; gy[51] = g[1]; gz[51] = g[2]; }
  { const v3d g = v3d{-0.12884115573246829, 1.1547146106222277, -0.18363787393782838, 0.0} + v3d{-0.67673213912366592, -0.63139541295016888, -0.00078690517195479455, 0.0}*m0 + v3d{0.21441815051075816, 0.084240529991751883, 0.66134474547065936, 0.0}*m2; gx[52] = g[0]; gy[52] = g[1]; gz[52] = g[2]; }
  { const v3d g = v3d{-0.081962082228368163, 1.1600585085276096, -0.17368766276564659, 0.0} + v3d{-0.70899207124150265, -0.61068612281328583, -0.0001143102685076432, 0.0}*m0 + v3d{0.24292559080521806, 0.089039981103242752, 0.66288629919518727, 0.0}*m2; gx[53] = g[0]; gy[53] = g[1]; gz[53] = g[2]; }
  { const v3d g = v3d{-0.91969487902748703, -0.35959194821971674, 0.16359349053005537, 0.0} + v3d{-0.0035266568609003276, 0.033478609411102228, 0.056460937380234291, 0.0}*m8 + v3d{-0.086064054231644885, 0.12892852386139669, -0.11485445856761589, 0.0}*m1 + v3d{0.16292432282621294, -0.36172062595511667, 0.025600951710077372, 0.0}*m7 + v3d{0.039774698776148525, -0.0040117473567698198, 0.14606121603723948, 0.0}*m4 + v3d{-0.065686417301255379, 0.16993872019177259, -0.0065771752895677762, 0.0}*m3 + v3d{-0.047222269629411888, -0.0082895995247486143, -0.22356631477627487, 0.0}*m21; gx[54] = g[0]; gy[54] = g[1]; gz[54] = g[2]; }
  { const v3d g = v3d{-0.78387139033565056, -0.57179733496918139, 0.2417359503209543, 0.0} + v3d{-0.054107241772602448, 0.065676898121946756, -0.037039412337452837, 0.0}*m8; gx[55] = g[0]; gy[55] = g[1]; gz[55] = g[2]; }
  { const v3d g = v3d{-0.79437711704699498, -0.53534754408988516, 0.28679598125280958, 0.0} + v3d{-0.062186022479536508, 0.076664482480672522, -0.049498382094632268, 0.0}*m8; gx[56] = g[0]; gy[56] = g[1]; gz[56] = g[2]; }
  { const v3d g = v3d{-0.89341805057964607, -0.35109031833683613, 0.28614975481665994, 0.0} + v3d{-0.074263100178920044, 0.077008540422802654, -0.14944391867394768, 0.0}*m2 + v3d{0.038258363959762301, -0.06327642642611056, 0.028232336740372621, 0.0}*m0; gx[57] = g[0]; gy[57] = g[1]; gz[57] = g[2]; }
  { const v3d g = v3d{-0.95920723134636798, -0.12684372132836688, 0.24227466162328773, 0.0} + v3d{-0.058208686264090752, 0.025639412040071478, -0.14451937627385852, 0.0}*m2 + v3d{-0.00087191005944131997, 0.12152752329850729, 0.040974102366489344, 0.0}*m3 + v3d{0.010603079369127355, 0.12630793302688006, -0.052323937764982273, 0.0}*m1 + v3d{0.010380880091031979, -0.19303019690150658, -0.02316801011516139, 0.0}*m7; gx[58] = g[0]; gy[58] = g[1]; gz[58] = g[2]; }
  { const v3d g = v3d{-0.91243902185528081, 0.094582312255022838, 0.38920617470322333, 0.0} + v3d{-0.084189585163824007, 0.22751096998258469, -0.33419350179694546, 0.0}*m5 + v3d{0.015961661160503612, 0.057591030274193045, 0.018104048367578555, 0.0}*m3 + v3d{0.00077703136026953618, -0.0047092472481938732, 0.0027457829379703529, 0.0}*m4 + v3d{-0.018328330017457647, -0.17271893588157236, 0.0070174328206945432, 0.0}*m0 + v3d{0.012923655414010238, -0.054406655211780897, 0.077588697316502239, 0.0}*m10 + v3d{0.044604139582853135, -0.0283612307332438, 0.090012583949671349, 0.0}*m11; gx[59] = g[0]; gy[59] = g[1]; gz[59] = g[2]; }
  { const v3d g = v3d{-0.89798854385679516, -0.37828777451642398, 0.2955089013114755, 0.0} + v3d{0.14441850539913922, -0.22003478768239709, -0.041270896579030027, 0.0}*m0 + v3d{0.04270171825614083, 0.013753452341968952, 0.089785283520805545, 0.0}*m10 + v3d{-0.096258858418168322, 0.068410367446613524, -0.060460579246309716, 0.0}*m5; gx[60] = g[0]; gy[60] = g[1]; gz[60] = g[2]; }
  { const v3d g = v3d{-0.87957650146872246, -0.40783020048880503, 0.29912468055081903, 0.0} + v3d{0.15366553118778437, -0.20493804811709715, 0.0043222013762005112, 0.0}*m0 + v3d{-0.072146668357793042, 0.04015094732953027, -0.084990069187907968, 0.0}*m1 + v3d{0.015243493482311729, 0.03202492795833365, 0.07600474952003608, 0.0}*m8; gx[61] = g[0]; gy[61] = g[1]; gz[61] = g[2]; }
  { const v3d g = v3d{-0.991564155916967, -0.17601844977299885, 0.25257998400711063, 0.0} + v3d{0.18836842956620337, -0.33783105181723172, 0.023643304994836408, 0.0}*m0 + v3d{-0.10942110062435075, 0.077918200951343372, -0.13448819826256675, 0.0}*m1 + v3d{0.064552482825073615, 0.044295459400119745, 0.19812371697036696, 0.0}*m8 + v3d{0.070189706404961388, -0.0021783221581013448, 0.18902188609567139, 0.0}*m4 + v3d{-0.060138812720008261, -0.030368200350427043, -0.2390414788962533, 0.0}*m18; gx[62] = g[0]; gy[62] = g[1]; gz[62] = g[2]; }
  { const v3d g = v3d{-0.92866003150496257, -0.14573638583656712, 0.3546640869081123, 0.0} + v3d{0.0029298739546671721, -0.11253270132942725, -0.078704794640871864, 0.0}*m7 + v3d{0.13066091363120355, -0.01719167701519677, 0.27275901594779883, 0.0}*m2; gx[63] = g[0]; gy[63] = g[1]; gz[63] = g[2]; }
  { const v3d g = v3d{-0.94389191128445993, -0.045655842869166879, 0.34516991733733604, 0.0} + v3d{0.00019476758996826263, -0.15421885772118815, -0.089956751663419598, 0.0}*m7 + v3d{0.14014415618759343, -0.020217607594209264, 0.30663263856693818, 0.0}*m2; gx[64] = g[0]; gy[64] = g[1]; gz[64] = g[2]; }
  { const v3d g = v3d{-0.88081106996365222, 0.17926700114522595, 0.49110733390989075, 0.0} + v3d{-0.055792314383958146, -0.30480788944691767, -0.16685424974988988, 0.0}*m0 + v3d{0.1669395921225095, -0.0031203796900774565, 0.30427681143327795, 0.0}*m2; gx[65] = g[0]; gy[65] = g[1]; gz[65] = g[2]; }
  { const v3d g = v3d{-0.89440187515150027, -0.15319703863757245, 0.44460993813156291, 0.0} + v3d{0.0098170757910351382, -0.055379395884875747, -0.015455682676607697, 0.0}*m8 + v3d{-0.004159377977463477, -0.14776944334897171, -0.12163854144210307, 0.0}*m0 + v3d{0.1122944687426022, 0.038804870881225681, 0.24095294052810759, 0.0}*m2; gx[66] = g[0]; gy[66] = g[1]; gz[66] = g[2]; }
  { const v3d g = v3d{-0.98733615200233249, 0.040454562193139837, 0.23225142202641375, 0.0} + v3d{0.12974320800528236, 0.020338608206796931, 0.29163391781152065, 0.0}*m4 + v3d{0.04699480821592434, -0.017175067346721404, 0.10001339754830885, 0.0}*m0 + v3d{0.0064658716342421542, 0.078717966762149774, -0.055816358077150907, 0.0}*m22 + v3d{-0.076376303074918092, -0.01865209335231955, -0.15846936101532372, 0.0}*m1 + v3d{0.092511710375708739, 0.0087322250950161266, 0.20737226832205416, 0.0}*m8; gx[67] = g[0]; gy[67] = g[1]; gz[67] = g[2]; }
  { const v3d g = v3d{-0.91389699512463474, 0.1187889721851966, 0.40626416488323081, 0.0} + v3d{0.1502020695846738, 0.014024924264089552, 0.23633035271346392, 0.0}*m4 + v3d{0.019012467162579132, 0.069441491649728099, -0.029022644481962147, 0.0}*m22 + v3d{-0.083442193885833682, -0.031854269792844968, -0.11887734910701929, 0.0}*m1 + v3d{0.033078280714872475, 0.011401137465350233, 0.046592398891219626, 0.0}*m3 + v3d{0.10058623208149851, 0.019887070388359612, 0.15920643229669718, 0.0}*m8; gx[68] = g[0]; gy[68] = g[1]; gz[68] = g[2]; }
  { const v3d g = v3d{-0.910784124106366, 0.24019292963321934, 0.33959658819218091, 0.0} + v3d{-0.028866759230929597, 0.031467678026881898, -0.12665117521643193, 0.0}*m1 + v3d{0.060645785608463093, 0.12359306683063306, 0.037680589527652721, 0.0}*m11 + v3d{0.011382524831951972, 0.018948885477305655, 0.01395995200736758, 0.0}*m3; gx[69] = g[0]; gy[69] = g[1]; gz[69] = g[2]; }
  { const v3d g = v3d{-0.93242007314014019, 0.28636357766910625, 0.23158841609741015, 0.0} + v3d{-0.010274537108520023, 0.043531596644658721, -0.19031426431586945, 0.0}*m1 + v3d{-0.031244014272401237, -0.18059071590547643, -0.0052403523076803467, 0.0}*m11 + v3d{0.022831555044736183, 0.046459377116115495, 0.020833996390586234, 0.0}*m3 + v3d{0.14573256478204319, 0.40038112444988594, 0.057907621659387974, 0.0}*m12; gx[70] = g[0]; gy[70] = g[1]; gz[70] = g[2]; }
  { const v3d g = v3d{-0.82732355835380955, -0.16800702320302793, 0.65958901188014496, 0.0} + v3d{0.049228782123198318, -0.14388249748310009, -0.21768886369998247, 0.0}*m22 + v3d{-0.031275725315964197, -0.21973654762877121, -0.0089142664486450106, 0.0}*m7 + v3d{-0.1588428021855138, 0.077063234966770269, -0.33404337214977986, 0.0}*m8 + v3d{0.061453910910991907, 0.034649791850282677, 0.041782253103308145, 0.0}*m12 + v3d{0.13664567335155969, 0.71002481804773321, -0.020120718710314258, 0.0}*m0 + v3d{-0.17142593421663777, 0.14497743934198579, -0.32698287912867519, 0.0}*m4; gx[71] = g[0]; gy[71] = g[1]; gz[71] = g[2]; }
  { const v3d g = v3d{-0.89186090137785068, 0.36503549340469404, 0.31892578884162859, 0.0} + v3d{-0.052021027904565281, -0.02365643228256498, -0.2788632628769846, 0.0}*m8 + v3d{0.11312911207464606, 0.19513389838833078, 0.013322694883706727, 0.0}*m0 + v3d{-0.034424211500622054, 0.0077260439906270536, -0.25101663187889134, 0.0}*m4; gx[72] = g[0]; gy[72] = g[1]; gz[72] = g[2]; }
  { const v3d g = v3d{-0.88368520488495506, -0.1303527435966155, 0.51461674574391125, 0.0} + v3d{0.013874598512821868, 0.2063535637147734, -0.013708218399121896, 0.0}*m0 + v3d{-0.0725409561305842, 0.0082646312172740197, -0.19453452393073295, 0.0}*m8 + v3d{-0.036490218181177259, 0.11792895042518413, -0.13111664894412242, 0.0}*m4; gx[73] = g[0]; gy[73] = g[1]; gz[73] = g[2]; }
  { const v3d g = v3d{-0.79825544625201961, -0.24704172375901368, 0.54943267890004677, 0.0} + v3d{-0.02958999469173574, 0.17384843397344713, 0.016544712005026337, 0.0}*m11 + v3d{-0.095181703737814233, -0.085651610919843094, -0.19231916009224409, 0.0}*m22; gx[74] = g[0]; gy[74] = g[1]; gz[74] = g[2]; }
  { const v3d g = v3d{-0.74564967555356754, -0.39910896371388699, 0.5340808740984061, 0.0} + v3d{-0.051268757070629799, 0.12530043055091281, 0.012273108271713564, 0.0}*m11 + v3d{-0.006970799205200281, -0.083894091376541552, -0.081450605715426186, 0.0}*m10; gx[75] = g[0]; gy[75] = g[1]; gz[75] = g[2]; }
  { const v3d g = v3d{-0.73996453948352381, -0.44554892017244635, 0.5034222485663965, 0.0} + v3d{-0.051906065456774585, 0.099771837071693389, 0.0053224251103655609, 0.0}*m11 + v3d{0.0084457110340285888, -0.074675109090272446, -0.059080549951347837, 0.0}*m9; gx[76] = g[0]; gy[76] = g[1]; gz[76] = g[2]; }
  { const v3d g = v3d{-0.69049014110684537, -0.5830161097073403, 0.42634107657241133, 0.0} + v3d{-0.038324691048084246, 0.069803104995713336, 0.027949317927106972, 0.0}*m0 + v3d{0.018610682514616391, -0.080161017028801712, -0.080963969578882952, 0.0}*m10; gx[77] = g[0]; gy[77] = g[1]; gz[77] = g[2]; }
  { const v3d g = v3d{-0.64926587302458705, -0.51549715069868451, 0.56070962385031098, 0.0} + v3d{-0.034386240636554384, 0.05986003256060099, 0.013512320632415222, 0.0}*m0 + v3d{0.0079448584529692168, -0.10774071239961118, -0.10292417651294332, 0.0}*m9 + v3d{-0.14012144431251161, 0.37996230103321388, 0.14153976791991971, 0.0}*m23 + v3d{-0.030424867084466435, -0.19924242503158868, -0.23954414996743867, 0.0}*m24; gx[78] = g[0]; gy[78] = g[1]; gz[78] = g[2]; }
  { const v3d g = v3d{-0.61112056121898151, -0.63984388520952851, 0.4716445457026503, 0.0} + v3d{-0.062743665241281721, 0.09862359025150795, 0.036409324265214177, 0.0}*m0 + v3d{0.022206112771947728, -0.082656203906296286, -0.082966517387653191, 0.0}*m10 + v3d{-0.072071203520204116, 0.022788108543249572, -0.089464928134794702, 0.0}*m4; gx[79] = g[0]; gy[79] = g[1]; gz[79] = g[2]; }
  { const v3d g = v3d{-0.79216412120812119, -0.166652540542639, 0.58666031851044698, 0.0} + v3d{0.033499928960152428, -0.062242490646737064, 0.044179493607607451, 0.0}*m4 + v3d{0.099338740512266238, -0.10420733142206759, 0.088323466706250103, 0.0}*m8 + v3d{-0.33206716180960522, 0.041171660035708983, -0.45804811471917239, 0.0}*m22 + v3d{0.24733895082476398, 0.05258975928812229, 0.41592138805623458, 0.0}*m21 + v3d{-0.16226997994983008, 0.11374018661712132, -0.22222704515266953, 0.0}*m12; gx[80] = g[0]; gy[80] = g[1]; gz[80] = g[2]; }
  { const v3d g = v3d{-0.84844966803717536, 0.056646592238479697, 0.52631605133174353, 0.0} + v3d{0.15872465570963348, -0.087653206284220728, 0.28588590029450883, 0.0}*m2 + v3d{-0.12125791675828296, 0.07536056554261035, -0.21712335427832594, 0.0}*m4 + v3d{-0.023062350039020962, -0.011964599807743314, -0.047518370172215461, 0.0}*m3 + v3d{-0.051724584708611958, 0.02800226956430418, -0.10988036728755289, 0.0}*m9; gx[81] = g[0]; gy[81] = g[1]; gz[81] = g[2]; }
  { const v3d g = v3d{-0.98348591961078602, -0.31037396065810652, -0.0033460595519053601, 0.0} + v3d{0.36092159942433855, 0.45735603450646123, -0.46198452023826397, 0.0}*m18 + v3d{0.013398588555557889, 0.099397710992718227, 0.027161750385387196, 0.0}*m3 + v3d{0.18662790052667438, 0.010801978935264245, 1.0822471178333413, 0.0}*m4 + v3d{0.36233542832124588, -0.019758856294310078, 1.0123626633729572, 0.0}*m8 + v3d{-0.22959856603844098, -0.09102386575790837, -0.24662696473664394, 0.0}*m1 + v3d{0.21836861784061684, 0.37091802595164314, -0.40667334882987233, 0.0}*m25 + v3d{0.017096518886366052, 0.21592263782801657, -0.26355294635426957, 0.0}*m10; gx[82] = g[0]; gy[82] = g[1]; gz[82] = g[2]; }
  { const v3d g = v3d{-0.063509053090537809, 0.97918332156253973, -0.021940197390190236, 0.0} + v3d{-1.0961170056391742, -0.15342992020420093, 0.095460575160652539, 0.0}*m0 + v3d{0.41840384112543128, 0.18548808339786668, 1.0457291887908793, 0.0}*m2 + v3d{0.109727500322754, -0.012911117404525923, -0.093051564922814203, 0.0}*m9 + v3d{0.085477502571648503, 0.093308655919076014, -0.014792182798500532, 0.0}*m4 + v3d{-0.11096717492084304, -0.11707761957024709, -0.27183204587746423, 0.0}*m1 + v3d{0.28516451296950446, -0.31206929229903146, -0.04391993371782809, 0.0}*m7 + v3d{-0.001930985731923163, -0.00071027199554155246, -0.0028008976741099013, 0.0}*m26; gx[83] = g[0]; gy[83] = g[1]; gz[83] = g[2]; }
  { const v3d g = v3d{-0.063509053090537809, 0.97918332156253973, -0.021940197390190236, 0.0} + v3d{-1.0961170056391742, -0.15342992020420093, 0.095460575160652539, 0.0}*m0 + v3d{0.41840384112543128, 0.18548808339786668, 1.0457291887908793, 0.0}*m2 + v3d{0.109727500322754, -0.012911117404525923, -0.093051564922814203, 0.0}*m9 + v3d{0.085477502571648503, 0.093308655919076014, -0.014792182798500532, 0.0}*m4 + v3d{-0.11096717492084304, -0.11707761957024709, -0.27183204587746423, 0.0}*m1 + v3d{0.28516451296950446, -0.31206929229903146, -0.04391993371782809, 0.0}*m7 + v3d{-0.001930985731923163, -0.00071027199554155246, -0.0028008976741099013, 0.0}*m26; gx[84] = g[0]; gy[84] = g[1]; gz[84] = g[2]; }
  { const v3d g = v3d{-0.29052802786077442, 1.1250860763156514, 0.080194347887203879, 0.0} + v3d{-0.57920744858939532, -0.69338015090683858, -0.073697962663685501, 0.0}*m0 + v3d{0.26243493626029024, -0.0076155356607488624, 0.65037363555262495, 0.0}*m2; gx[85] = g[0]; gy[85] = g[1]; gz[85] = g[2]; }
  { const v3d g = v3d{-0.24982488403492206, 1.0913828405809824, -0.038155875401272493, 0.0} + v3d{-0.62909650323326893, -0.67877066099403438, -0.0014365456261743259, 0.0}*m0 + v3d{0.11688543954307618, 0.19633507702105105, 1.0954839949750892, 0.0}*m2 + v3d{0.13507069102296754, -0.17333853323388496, -0.36196163582028268, 0.0}*m1; gx[86] = g[0]; gy[86] = g[1]; gz[86] = g[2]; }
  { const v3d g = v3d{-0.23869992488546996, 1.0942870876952657, -0.0046167228569437479, 0.0} + v3d{-0.63492060007960116, -0.67204146162635425, -0.0026730585139428417, 0.0}*m0 + v3d{0.13395852775875, 0.16888306353873203, 1.0717234466313965, 0.0}*m2 + v3d{0.13250192674059352, -0.15693758078316089, -0.35227754131338018, 0.0}*m1; gx[87] = g[0]; gy[87] = g[1]; gz[87] = g[2]; }
  { const v3d g = v3d{-0.2545570808335656, 1.0902569687374932, -0.031954748058019483, 0.0} + v3d{-0.62655814131214538, -0.68212167332204188, -0.0058891245165731019, 0.0}*m0 + v3d{0.12182449511559457, 0.19403272735742905, 1.1041355601942189, 0.0}*m2 + v3d{0.1328833822717409, -0.17296938532524364, -0.36701423526091115, 0.0}*m1; gx[88] = g[0]; gy[88] = g[1]; gz[88] = g[2]; }
  { const v3d g = v3d{-0.79793787755119305, -0.64461501041843605, 0.099728465942052105, 0.0} + v3d{-0.51816442639897031, 1.150602405781824, -0.021747241497973597, 0.0}*m27 + v3d{1.5244246796883472, -2.7467985403890931, 0.70154755602764673, 0.0}*m28 + v3d{-0.38133326143954221, 0.6213345169686848, -0.21245557376117849, 0.0}*m29 + v3d{-0.097189331925000511, 0.12098728451983058, -0.26263992939281061, 0.0}*m30; gx[89] = g[0]; gy[89] = g[1]; gz[89] = g[2]; }
  { const v3d g = v3d{0.19001626325443549, -1.7094189800173705, -0.13180739954946388, 0.0} + v3d{0.036378736890058064, 0.43268766954235682, -0.081058151486791158, 0.0}*m27 + v3d{-1.3188975946898385, 1.4653916891944458, 0.22004175098181888, 0.0}*m31 + v3d{-0.1145536055234158, 0.12623832360034157, -0.2880407034148918, 0.0}*m30 + v3d{2.0175422288856586, -1.5062128501420771, 0.3178952069501827, 0.0}*m32 + v3d{-0.67159644917884054, 0.26443564465699165, -0.61577322997155381, 0.0}*m33; gx[90] = g[0]; gy[90] = g[1]; gz[90] = g[2]; }
  { const v3d g = v3d{0.30698065355767579, -1.6168484430061143, -0.4323007625926048, 0.0} + v3d{-0.10615065467687501, 0.81906047676441895, 0.0029252026716706271, 0.0}*m27 + v3d{-1.3658217588038941, 1.1514850046301524, 0.4942877077984616, 0.0}*m31 + v3d{-0.10917168849525807, 0.11594632612746572, -0.25907812275824643, 0.0}*m30 + v3d{2.5451935802157881, -1.0727787226580823, 0.20871326858456046, 0.0}*m32 + v3d{0.73063281485474885, -0.10641100402161295, 0.48672673316262971, 0.0}*m34; gx[91] = g[0]; gy[91] = g[1]; gz[91] = g[2]; }
  { const v3d g = v3d{0.90945243411178445, -1.5158448444364863, -0.50042074302364714, 0.0} + v3d{-1.0505279812545112, 0.97032335786032398, -0.38867061116291002, 0.0}*m27 + v3d{-1.8448718895293756, 0.82943588180277539, 0.64368066144689595, 0.0}*m31 + v3d{1.2851953150635047, -0.52955095469741975, -0.48560235148963049, 0.0}*m35; gx[92] = g[0]; gy[92] = g[1]; gz[92] = g[2]; }
  { const v3d g = v3d{1.530748837202883, -0.86155885355511852, -0.37750320344796817, 0.0} + v3d{6.0428389640551412, 4.795379434179444, 3.0831295678043911, 0.0}*m27 + v3d{-2.5281415457727454, -0.23356447064654412, 0.36083945623402403, 0.0}*m31 + v3d{-5.6336315936804349, -2.4879248843620925, -2.2543530165761569, 0.0}*m36 + v3d{-0.43492067748257468, 0.28155703759166451, 0.015361323438208391, 0.0}*m37 + v3d{-0.26030040513628772, 0.14810599467284435, 0.52926258714145791, 0.0}*m38 + v3d{0.25548661181974941, -0.33523645130990687, -0.35704549763422166, 0.0}*m39; gx[93] = g[0]; gy[93] = g[1]; gz[93] = g[2]; }
  { const v3d g = v3d{1.3781346824767797, -0.68558417872930089, -0.92632848320900785, 0.0} + v3d{-3.3210603498661588, 0.56326665124527531, -1.0885749499033883, 0.0}*m27 + v3d{-4.7977322166665957, -3.131257519894707, 1.387826415779948, 0.0}*m40 + v3d{0.15813415368498204, -0.046619722139119274, -0.040673949655583061, 0.0}*m8 + v3d{-2.0758855440390631, -0.47788875539618592, 1.2326641470204927, 0.0}*m31 + v3d{0.64485152599574613, 0.26898795631447175, 0.5818757554640247, 0.0}*m41 + v3d{-0.23578564290267262, 0.0699486099479113, 0.32722536179281109, 0.0}*m42 + v3d{3.4486643621381701, 2.0266929688929842, -1.1189935065551198, 0.0}*m43; gx[94] = g[0]; gy[94] = g[1]; gz[94] = g[2]; }
  { const v3d g = v3d{-0.25450528931197708, -0.31830239228760232, -0.93547143110827202, 0.0} + v3d{-1.0574576304770591, -0.23090898444022206, 0.45996542775867261, 0.0}*m16 + v3d{-0.89905857197896399, 0.13282164861044546, 0.8659642156086047, 0.0}*m27 + v3d{-0.71205600057424101, -0.054587678804834984, 0.34895998990926497, 0.0}*m44 + v3d{0.29872347449143394, 0.44224978754066757, -0.41358524095058397, 0.0}*m45 + v3d{0.43661085318381948, -0.0025217937260669523, -0.078485875985550943, 0.0}*m15 + v3d{1.3661898800230863, 0.33333395786112074, -0.54288563760679098, 0.0}*m32; gx[95] = g[0]; gy[95] = g[1]; gz[95] = g[2]; }
  { const v3d g = v3d{-0.52568975604257029, -0.13291605946688301, -0.87595567716118639, 0.0} + v3d{-0.12060388480539426, -0.40542615241671376, 0.2833166345800236, 0.0}*m16 + v3d{2.7676979839373215, 3.2447693877891739, -2.096732581175925, 0.0}*m27 + v3d{0.22361203943540395, 0.27711237422309942, -0.29468023870127752, 0.0}*m45 + v3d{0.71076635922926101, -0.02722614183915709, -0.44076431142929362, 0.0}*m46 + v3d{-2.5520422813171626, -2.0685507407331949, 2.0155201675847567, 0.0}*m36; gx[96] = g[0]; gy[96] = g[1]; gz[96] = g[2]; }
  { const v3d g = v3d{-0.56295289620389977, -0.10321945364394225, -0.82840033746192077, 0.0} + v3d{-0.32224352142457979, -0.15969498499592061, 0.28779365730487172, 0.0}*m7 + v3d{-0.69839198144749071, 0.13026353009581981, 0.6537419549156871, 0.0}*m36 + v3d{0.21173764353574906, 0.046656244572718782, -0.16293270722152603, 0.0}*m3 + v3d{-0.024401448529819528, -0.075507030936989045, 0.063402510870923759, 0.0}*m1 + v3d{-0.22733494400356888, -0.08770413871764221, 0.22974079293584854, 0.0}*m47; gx[97] = g[0]; gy[97] = g[1]; gz[97] = g[2]; }
  { const v3d g = v3d{-0.48846088694739515, -0.021561322533116031, -0.88008286734720553, 0.0} + v3d{-0.96888035031626429, -0.1332656052482428, 0.68400603808254989, 0.0}*m16 + v3d{-5.0651906221649448, -2.7980039319780547, 4.0225715698141808, 0.0}*m36 + v3d{7.0984916758123466, 4.4441384934658661, -5.5262797822626428, 0.0}*m27 + v3d{0.19283203740010721, -0.12416588604688082, -0.084974792176831529, 0.0}*m7 + v3d{0.52412026600130546, 0.58626198726246426, -0.57867855534552759, 0.0}*m48; gx[98] = g[0]; gy[98] = g[1]; gz[98] = g[2]; }
  { const v3d g = v3d{-0.68609587723829613, 0.21228897987186859, -0.69073780070474344, 0.0} + v3d{-0.21039214081980076, -0.095600796760883427, 0.21083261753022797, 0.0}*m0 + v3d{0.4539961752544488, 0.75808773547245389, -0.43096564076373184, 0.0}*m48 + v3d{0.046179030987703117, -0.036969501369314463, -0.045872058635441193, 0.0}*m3; gx[99] = g[0]; gy[99] = g[1]; gz[99] = g[2]; }
  { const v3d g = v3d{-0.67736917074789249, 0.39458213302739242, -0.62762808435963868, 0.0} + v3d{-0.32034833684163927, -0.2039946789673496, 0.31484487924678095, 0.0}*m0 + v3d{0.16824410357619971, -0.056843051357257132, -0.20267290267452287, 0.0}*m15 + v3d{0.087385332271651225, 0.21125895603574846, -0.053978859278546808, 0.0}*m17 + v3d{-0.026097364608450063, 0.084144364082823192, 0.099415477915756931, 0.0}*m14; gx[100] = g[0]; gy[100] = g[1]; gz[100] = g[2]; }
  { const v3d g = v3d{-0.66504367824809463, 0.74951673239996253, -0.29699585661722638, 0.0} + v3d{-0.18290338213928961, -0.34847210423938729, -0.033769231414522274, 0.0}*m0 + v3d{-0.17365688366690485, 0.023230039433689533, 0.34132384078075517, 0.0}*m2 + v3d{-0.35864695110258937, -0.31176129417809534, 0.12932159480959687, 0.0}*m49 + v3d{0.36750292418598068, 0.20452161139838634, -0.12991935211770669, 0.0}*m50; gx[101] = g[0]; gy[101] = g[1]; gz[101] = g[2]; }
  { const v3d g = v3d{-0.72700750886527821, 0.66483597881572454, -0.26687631379261123, 0.0} + v3d{-0.13507881608032285, -0.25649278351739901, -0.044263705219640681, 0.0}*m0 + v3d{0.50464132139235207, 0.29874804274690087, -0.24512431194546958, 0.0}*m50 + v3d{-0.50833421464656703, -0.61540725137295016, 0.10299757138972788, 0.0}*m51 + v3d{-0.17620460868975332, 0.016524224809117895, 0.27816820433519335, 0.0}*m2; gx[102] = g[0]; gy[102] = g[1]; gz[102] = g[2]; }
  gx[103] = 0.0; gy[103] = 0.0; gz[103] = 0.0;
  gx[104] = 0.0; gy[104] = 0.0; gz[104] = 0.0;
  gx[105] = 0.0; gy[105] = 0.0; gz[105] = 0.0;
  gx[106] = 0.0; gy[106] = 0.0; gz[106] = 0.0;
  gx[107] = 0.0; gy[107] = 0.0; gz[107] = 0.0;
  gx[108] = 0.0; gy[108] = 0.0; gz[108] = 0.0;
  gx[109] = 0.0; gy[109] = 0.0; gz[109] = 0.0;
  gx[110] = 0.0; gy[110] = 0.0; gz[110] = 0.0;
  gx[111] = 0.0; gy[111] = 0.0; gz[111] = 0.0;
  gx[112] = 0.0; gy[112] = 0.0; gz[112] = 0.0;
  gx[113] = 0.0; gy[113] = 0.0; gz[113] = 0.0;
  gx[114] = 0.0; gy[114] = 0.0; gz[114] = 0.0;
  gx[115] = 0.0; gy[115] = 0.0; gz[115] = 0.0;
  gx[116] = 0.0; gy[116] = 0.0; gz[116] = 0.0;
  gx[117] = 0.0; gy[117] = 0.0; gz[117] = 0.0;
  gx[118] = 0.0; gy[118] = 0.0; gz[118] = 0.0;
  gx[119] = 0.0; gy[119] = 0.0; gz[119] = 0.0;
  gx[120] = 0.0; gy[120] = 0.0; gz[120] = 0.0;
  gx[121] = 0.0; gy[121] = 0.0; gz[121] = 0.0;
  gx[122] = 0.0; gy[122] = 0.0; gz[122] = 0.0;
  gx[123] = 0.0; gy[123] = 0.0; gz[123] = 0.0;
  gx[124] = 0.0; gy[124] = 0.0; gz[124] = 0.0;
  gx[125] = 0.0; gy[125] = 0.0; gz[125] = 0.0;
  gx[126] = 0.0; gy[126] = 0.0; gz[126] = 0.0;
  gx[127] = 0.0; gy[127] = 0.0; gz[127] = 0.0;
  gx[128] = 0.0; gy[128] = 0.0; gz[128] = 0.0;
  gx[129] = 0.0; gy[129] = 0.0; gz[129] = 0.0;
  gx[130] = 0.0; gy[130] = 0.0; gz[130] = 0.0;
  gx[131] = 0.0; gy[131] = 0.0; gz[131] = 0.0;
  gx[132] = 0.0; gy[132] = 0.0; gz[132] = 0.0;
  gx[133] = 0.0; gy[133] = 0.0; gz[133] = 0.0;
  gx[134] = 0.0; gy[134] = 0.0; gz[134] = 0.0;
  gx[135] = 0.0; gy[135] = 0.0; gz[135] = 0.0;
  gx[136] = 0.0; gy[136] = 0.0; gz[136] = 0.0;
  gx[137] = 0.0; gy[137] = 0.0; gz[137] = 0.0;
  for (int i = 0; i < 138; ++i) {
    const double n2 = gx[i]*gx[i] + gy[i]*gy[i] + gz[i]*gz[i];
    const double s = n2 > 0.0 ? 1.0/std::sqrt(n2) : 0.0;
    d[3*i] = gx[i]*s; d[3*i + 1] = gy[i]*s; d[3*i + 2] = gz[i]*s;
  }
}

}  // namespace armrt::generated::das3
