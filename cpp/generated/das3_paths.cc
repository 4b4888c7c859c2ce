// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das3.json --out cpp/generated`
// from the model file das3.json (sha256 0f674927e0fc296ed25b403711106e5fecdfde98bb37ed4ed146458c848d9487).
// Change the model file or the generator and regenerate instead.

#include <cmath>
#include <cstring>

#include "das3.h"

namespace armrt::generated::das3 {

// Eight doubles, one SIMD register with AVX-512 (two with AVX2): one block of an element's moment arms and its length.
using v8d = double __attribute__((vector_size(64)));

void muscle_lengths(const double* q, double* L) {
  double moment_arm[1518];
  muscle_paths(q, L, moment_arm);
}

void muscle_paths(const double* q, double* L, double* moment_arm) {
  // DOFs 0..5 in block 0, 6..10 in block 1 (_blocked_paths).
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
  const v8d g_one_0 = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0};
  const v8d g_one_1 = {0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  const v8d e0 = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e1 = {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e2 = {0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e3 = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e4 = {0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};
  const v8d e5 = {0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  const v8d e6 = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e7 = {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e8 = {0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e9 = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e10 = {0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0};
  const double p0 = q10;
  const v8d g0_0 = q10*g_one_0;
  const v8d g0_1 = q10*g_one_1 - e10;
  const double p1 = q9;
  const v8d g1_0 = q9*g_one_0;
  const v8d g1_1 = q9*g_one_1 - e9;
  const double p2 = q8;
  const v8d g2_0 = q8*g_one_0;
  const v8d g2_1 = q8*g_one_1 - e8;
  const double p3 = q7;
  const v8d g3_0 = q7*g_one_0;
  const v8d g3_1 = q7*g_one_1 - e7;
  const double p4 = q6;
  const v8d g4_0 = q6*g_one_0;
  const v8d g4_1 = q6*g_one_1 - e6;
  const double p5 = q5;
  const v8d g5_0 = q5*g_one_0 - e5;
  const v8d g5_1 = q5*g_one_1;
  const double p6 = q4;
  const v8d g6_0 = q4*g_one_0 - e4;
  const v8d g6_1 = q4*g_one_1;
  const double p7 = q3;
  const v8d g7_0 = q3*g_one_0 - e3;
  const v8d g7_1 = q3*g_one_1;
  const double p8 = q2;
  const v8d g8_0 = q2*g_one_0 - e2;
  const v8d g8_1 = q2*g_one_1;
  const double p9 = q1;
  const v8d g9_0 = q1*g_one_0 - e1;
  const v8d g9_1 = q1*g_one_1;
  const double p10 = q0;
  const v8d g10_0 = q0*g_one_0 - e0;
  const v8d g10_1 = q0*g_one_1;
  const double p11 = q10*p0;
  const v8d g11_0 = q10*g0_0;
  const v8d g11_1 = q10*g0_1 - p0*e10;
  const double p12 = q10*p1;
  const v8d g12_0 = q10*g1_0;
  const v8d g12_1 = q10*g1_1 - p1*e10;
  const double p13 = q9*p1;
  const v8d g13_0 = q9*g1_0;
  const v8d g13_1 = q9*g1_1 - p1*e9;
  const double p14 = q9*p2;
  const v8d g14_0 = q9*g2_0;
  const v8d g14_1 = q9*g2_1 - p2*e9;
  const double p15 = q8*p2;
  const v8d g15_0 = q8*g2_0;
  const v8d g15_1 = q8*g2_1 - p2*e8;
  const double p16 = q8*p3;
  const v8d g16_0 = q8*g3_0;
  const v8d g16_1 = q8*g3_1 - p3*e8;
  const double p17 = q7*p3;
  const v8d g17_0 = q7*g3_0;
  const v8d g17_1 = q7*g3_1 - p3*e7;
  const double p18 = q8*p4;
  const v8d g18_0 = q8*g4_0;
  const v8d g18_1 = q8*g4_1 - p4*e8;
  const double p19 = q7*p4;
  const v8d g19_0 = q7*g4_0;
  const v8d g19_1 = q7*g4_1 - p4*e7;
  const double p20 = q6*p4;
  const v8d g20_0 = q6*g4_0;
  const v8d g20_1 = q6*g4_1 - p4*e6;
  const double p21 = q8*p5;
  const v8d g21_0 = q8*g5_0;
  const v8d g21_1 = q8*g5_1 - p5*e8;
  const double p22 = q7*p5;
  const v8d g22_0 = q7*g5_0;
  const v8d g22_1 = q7*g5_1 - p5*e7;
  const double p23 = q6*p5;
  const v8d g23_0 = q6*g5_0;
  const v8d g23_1 = q6*g5_1 - p5*e6;
  const double p24 = q5*p5;
  const v8d g24_0 = q5*g5_0 - p5*e5;
  const v8d g24_1 = q5*g5_1;
  const double p25 = q8*p6;
  const v8d g25_0 = q8*g6_0;
  const v8d g25_1 = q8*g6_1 - p6*e8;
  const double p26 = q7*p6;
  const v8d g26_0 = q7*g6_0;
  const v8d g26_1 = q7*g6_1 - p6*e7;
  const double p27 = q6*p6;
  const v8d g27_0 = q6*g6_0;
  const v8d g27_1 = q6*g6_1 - p6*e6;
  const double p28 = q5*p6;
  const v8d g28_0 = q5*g6_0 - p6*e5;
  const v8d g28_1 = q5*g6_1;
  const double p29 = q4*p6;
  const v8d g29_0 = q4*g6_0 - p6*e4;
  const v8d g29_1 = q4*g6_1;
  const double p30 = q8*p7;
  const v8d g30_0 = q8*g7_0;
  const v8d g30_1 = q8*g7_1 - p7*e8;
  const double p31 = q7*p7;
  const v8d g31_0 = q7*g7_0;
  const v8d g31_1 = q7*g7_1 - p7*e7;
  const double p32 = q6*p7;
  const v8d g32_0 = q6*g7_0;
  const v8d g32_1 = q6*g7_1 - p7*e6;
  const double p33 = q5*p7;
  const v8d g33_0 = q5*g7_0 - p7*e5;
  const v8d g33_1 = q5*g7_1;
  const double p34 = q4*p7;
  const v8d g34_0 = q4*g7_0 - p7*e4;
  const v8d g34_1 = q4*g7_1;
  const double p35 = q3*p7;
  const v8d g35_0 = q3*g7_0 - p7*e3;
  const v8d g35_1 = q3*g7_1;
  const v8d g36_0 = q8*g8_0;
  const v8d g36_1 = q8*g8_1 - p8*e8;
  const double p37 = q7*p8;
  const v8d g37_0 = q7*g8_0;
  const v8d g37_1 = q7*g8_1 - p8*e7;
  const double p38 = q6*p8;
  const v8d g38_0 = q6*g8_0;
  const v8d g38_1 = q6*g8_1 - p8*e6;
  const double p39 = q5*p8;
  const v8d g39_0 = q5*g8_0 - p8*e5;
  const v8d g39_1 = q5*g8_1;
  const double p40 = q4*p8;
  const v8d g40_0 = q4*g8_0 - p8*e4;
  const v8d g40_1 = q4*g8_1;
  const double p41 = q3*p8;
  const v8d g41_0 = q3*g8_0 - p8*e3;
  const v8d g41_1 = q3*g8_1;
  const double p42 = q2*p8;
  const v8d g42_0 = q2*g8_0 - p8*e2;
  const v8d g42_1 = q2*g8_1;
  const double p43 = q8*p9;
  const v8d g43_0 = q8*g9_0;
  const v8d g43_1 = q8*g9_1 - p9*e8;
  const double p44 = q7*p9;
  const v8d g44_0 = q7*g9_0;
  const v8d g44_1 = q7*g9_1 - p9*e7;
  const double p45 = q6*p9;
  const v8d g45_0 = q6*g9_0;
  const v8d g45_1 = q6*g9_1 - p9*e6;
  const double p46 = q5*p9;
  const v8d g46_0 = q5*g9_0 - p9*e5;
  const v8d g46_1 = q5*g9_1;
  const double p47 = q4*p9;
  const v8d g47_0 = q4*g9_0 - p9*e4;
  const v8d g47_1 = q4*g9_1;
  const double p48 = q3*p9;
  const v8d g48_0 = q3*g9_0 - p9*e3;
  const v8d g48_1 = q3*g9_1;
  const double p49 = q2*p9;
  const v8d g49_0 = q2*g9_0 - p9*e2;
  const v8d g49_1 = q2*g9_1;
  const double p50 = q1*p9;
  const v8d g50_0 = q1*g9_0 - p9*e1;
  const v8d g50_1 = q1*g9_1;
  const v8d g51_0 = q8*g10_0;
  const v8d g51_1 = q8*g10_1 - p10*e8;
  const double p52 = q7*p10;
  const v8d g52_0 = q7*g10_0;
  const v8d g52_1 = q7*g10_1 - p10*e7;
  const double p53 = q6*p10;
  const v8d g53_0 = q6*g10_0;
  const v8d g53_1 = q6*g10_1 - p10*e6;
  const double p54 = q5*p10;
  const v8d g54_0 = q5*g10_0 - p10*e5;
  const v8d g54_1 = q5*g10_1;
  const double p55 = q4*p10;
  const v8d g55_0 = q4*g10_0 - p10*e4;
  const v8d g55_1 = q4*g10_1;
  const double p56 = q3*p10;
  const v8d g56_0 = q3*g10_0 - p10*e3;
  const v8d g56_1 = q3*g10_1;
  const double p57 = q2*p10;
  const v8d g57_0 = q2*g10_0 - p10*e2;
  const v8d g57_1 = q2*g10_1;
  const double p58 = q1*p10;
  const v8d g58_0 = q1*g10_0 - p10*e1;
  const v8d g58_1 = q1*g10_1;
  const double p59 = q0*p10;
  const v8d g59_0 = q0*g10_0 - p10*e0;
  const v8d g59_1 = q0*g10_1;
  const double p60 = q10*p11;
  const v8d g60_0 = q10*g11_0;
  const v8d g60_1 = q10*g11_1 - p11*e10;
  const double p61 = q10*p12;
  const v8d g61_0 = q10*g12_0;
  const v8d g61_1 = q10*g12_1 - p12*e10;
  const double p62 = q10*p13;
  const v8d g62_0 = q10*g13_0;
  const v8d g62_1 = q10*g13_1 - p13*e10;
  const double p63 = q9*p13;
  const v8d g63_0 = q9*g13_0;
  const v8d g63_1 = q9*g13_1 - p13*e9;
  const double p64 = q9*p14;
  const v8d g64_0 = q9*g14_0;
  const v8d g64_1 = q9*g14_1 - p14*e9;
  const v8d g65_0 = q9*g15_0;
  const v8d g65_1 = q9*g15_1 - p15*e9;
  const double p66 = q8*p15;
  const v8d g66_0 = q8*g15_0;
  const v8d g66_1 = q8*g15_1 - p15*e8;
  const double p67 = q8*p16;
  const v8d g67_0 = q8*g16_0;
  const v8d g67_1 = q8*g16_1 - p16*e8;
  const double p68 = q8*p17;
  const v8d g68_0 = q8*g17_0;
  const v8d g68_1 = q8*g17_1 - p17*e8;
  const double p69 = q7*p17;
  const v8d g69_0 = q7*g17_0;
  const v8d g69_1 = q7*g17_1 - p17*e7;
  const double p70 = q8*p18;
  const v8d g70_0 = q8*g18_0;
  const v8d g70_1 = q8*g18_1 - p18*e8;
  const double p71 = q8*p19;
  const v8d g71_0 = q8*g19_0;
  const v8d g71_1 = q8*g19_1 - p19*e8;
  const double p72 = q7*p19;
  const v8d g72_0 = q7*g19_0;
  const v8d g72_1 = q7*g19_1 - p19*e7;
  const double p73 = q8*p20;
  const v8d g73_0 = q8*g20_0;
  const v8d g73_1 = q8*g20_1 - p20*e8;
  const double p74 = q7*p20;
  const v8d g74_0 = q7*g20_0;
  const v8d g74_1 = q7*g20_1 - p20*e7;
  const double p75 = q6*p20;
  const v8d g75_0 = q6*g20_0;
  const v8d g75_1 = q6*g20_1 - p20*e6;
  const v8d g76_0 = q8*g21_0;
  const v8d g76_1 = q8*g21_1 - p21*e8;
  const v8d g77_0 = q8*g22_0;
  const v8d g77_1 = q8*g22_1 - p22*e8;
  const v8d g78_0 = q7*g22_0;
  const v8d g78_1 = q7*g22_1 - p22*e7;
  const v8d g79_0 = q8*g23_0;
  const v8d g79_1 = q8*g23_1 - p23*e8;
  const v8d g80_0 = q7*g23_0;
  const v8d g80_1 = q7*g23_1 - p23*e7;
  const v8d g81_0 = q6*g23_0;
  const v8d g81_1 = q6*g23_1 - p23*e6;
  const v8d g82_0 = q7*g24_0;
  const v8d g82_1 = q7*g24_1 - p24*e7;
  const v8d g83_0 = q6*g24_0;
  const v8d g83_1 = q6*g24_1 - p24*e6;
  const v8d g84_0 = q5*g24_0 - p24*e5;
  const v8d g84_1 = q5*g24_1;
  const v8d g85_0 = q8*g25_0;
  const v8d g85_1 = q8*g25_1 - p25*e8;
  const v8d g86_0 = q8*g26_0;
  const v8d g86_1 = q8*g26_1 - p26*e8;
  const v8d g87_0 = q7*g26_0;
  const v8d g87_1 = q7*g26_1 - p26*e7;
  const v8d g88_0 = q8*g27_0;
  const v8d g88_1 = q8*g27_1 - p27*e8;
  const v8d g89_0 = q7*g27_0;
  const v8d g89_1 = q7*g27_1 - p27*e7;
  const v8d g90_0 = q6*g27_0;
  const v8d g90_1 = q6*g27_1 - p27*e6;
  const v8d g91_0 = q8*g28_0;
  const v8d g91_1 = q8*g28_1 - p28*e8;
  const v8d g92_0 = q7*g28_0;
  const v8d g92_1 = q7*g28_1 - p28*e7;
  const v8d g93_0 = q6*g28_0;
  const v8d g93_1 = q6*g28_1 - p28*e6;
  const v8d g94_0 = q5*g28_0 - p28*e5;
  const v8d g94_1 = q5*g28_1;
  const v8d g95_0 = q8*g29_0;
  const v8d g95_1 = q8*g29_1 - p29*e8;
  const v8d g96_0 = q7*g29_0;
  const v8d g96_1 = q7*g29_1 - p29*e7;
  const v8d g97_0 = q6*g29_0;
  const v8d g97_1 = q6*g29_1 - p29*e6;
  const v8d g98_0 = q5*g29_0 - p29*e5;
  const v8d g98_1 = q5*g29_1;
  const v8d g99_0 = q4*g29_0 - p29*e4;
  const v8d g99_1 = q4*g29_1;
  const v8d g100_0 = q8*g30_0;
  const v8d g100_1 = q8*g30_1 - p30*e8;
  const v8d g101_0 = q8*g31_0;
  const v8d g101_1 = q8*g31_1 - p31*e8;
  const v8d g102_0 = q7*g31_0;
  const v8d g102_1 = q7*g31_1 - p31*e7;
  const v8d g103_0 = q8*g32_0;
  const v8d g103_1 = q8*g32_1 - p32*e8;
  const v8d g104_0 = q7*g32_0;
  const v8d g104_1 = q7*g32_1 - p32*e7;
  const v8d g105_0 = q6*g32_0;
  const v8d g105_1 = q6*g32_1 - p32*e6;
  const v8d g106_0 = q8*g33_0;
  const v8d g106_1 = q8*g33_1 - p33*e8;
  const v8d g107_0 = q7*g33_0;
  const v8d g107_1 = q7*g33_1 - p33*e7;
  const v8d g108_0 = q6*g33_0;
  const v8d g108_1 = q6*g33_1 - p33*e6;
  const v8d g109_0 = q5*g33_0 - p33*e5;
  const v8d g109_1 = q5*g33_1;
  const v8d g110_0 = q8*g34_0;
  const v8d g110_1 = q8*g34_1 - p34*e8;
  const v8d g111_0 = q7*g34_0;
  const v8d g111_1 = q7*g34_1 - p34*e7;
  const v8d g112_0 = q6*g34_0;
  const v8d g112_1 = q6*g34_1 - p34*e6;
  const v8d g113_0 = q5*g34_0 - p34*e5;
  const v8d g113_1 = q5*g34_1;
  const v8d g114_0 = q4*g34_0 - p34*e4;
  const v8d g114_1 = q4*g34_1;
  const v8d g115_0 = q8*g35_0;
  const v8d g115_1 = q8*g35_1 - p35*e8;
  const v8d g116_0 = q7*g35_0;
  const v8d g116_1 = q7*g35_1 - p35*e7;
  const v8d g117_0 = q6*g35_0;
  const v8d g117_1 = q6*g35_1 - p35*e6;
  const v8d g118_0 = q5*g35_0 - p35*e5;
  const v8d g118_1 = q5*g35_1;
  const v8d g119_0 = q4*g35_0 - p35*e4;
  const v8d g119_1 = q4*g35_1;
  const v8d g120_0 = q3*g35_0 - p35*e3;
  const v8d g120_1 = q3*g35_1;
  const v8d g121_0 = q8*g37_0;
  const v8d g121_1 = q8*g37_1 - p37*e8;
  const v8d g122_0 = q7*g37_0;
  const v8d g122_1 = q7*g37_1 - p37*e7;
  const v8d g123_0 = q8*g38_0;
  const v8d g123_1 = q8*g38_1 - p38*e8;
  const v8d g124_0 = q7*g38_0;
  const v8d g124_1 = q7*g38_1 - p38*e7;
  const v8d g125_0 = q6*g38_0;
  const v8d g125_1 = q6*g38_1 - p38*e6;
  const v8d g126_0 = q8*g39_0;
  const v8d g126_1 = q8*g39_1 - p39*e8;
  const v8d g127_0 = q7*g39_0;
  const v8d g127_1 = q7*g39_1 - p39*e7;
  const v8d g128_0 = q5*g39_0 - p39*e5;
  const v8d g128_1 = q5*g39_1;
  const v8d g129_0 = q8*g40_0;
  const v8d g129_1 = q8*g40_1 - p40*e8;
  const v8d g130_0 = q7*g40_0;
  const v8d g130_1 = q7*g40_1 - p40*e7;
  const v8d g131_0 = q5*g40_0 - p40*e5;
  const v8d g131_1 = q5*g40_1;
  const v8d g132_0 = q4*g40_0 - p40*e4;
  const v8d g132_1 = q4*g40_1;
  const v8d g133_0 = q8*g41_0;
  const v8d g133_1 = q8*g41_1 - p41*e8;
  const v8d g134_0 = q7*g41_0;
  const v8d g134_1 = q7*g41_1 - p41*e7;
  const v8d g135_0 = q5*g41_0 - p41*e5;
  const v8d g135_1 = q5*g41_1;
  const v8d g136_0 = q4*g41_0 - p41*e4;
  const v8d g136_1 = q4*g41_1;
  const v8d g137_0 = q3*g41_0 - p41*e3;
  const v8d g137_1 = q3*g41_1;
  const v8d g138_0 = q8*g42_0;
  const v8d g138_1 = q8*g42_1 - p42*e8;
  const v8d g139_0 = q7*g42_0;
  const v8d g139_1 = q7*g42_1 - p42*e7;
  const v8d g140_0 = q5*g42_0 - p42*e5;
  const v8d g140_1 = q5*g42_1;
  const v8d g141_0 = q4*g42_0 - p42*e4;
  const v8d g141_1 = q4*g42_1;
  const v8d g142_0 = q3*g42_0 - p42*e3;
  const v8d g142_1 = q3*g42_1;
  const double p143 = q2*p42;
  const v8d g143_0 = q2*g42_0 - p42*e2;
  const v8d g143_1 = q2*g42_1;
  const v8d g144_0 = q8*g43_0;
  const v8d g144_1 = q8*g43_1 - p43*e8;
  const v8d g145_0 = q7*g44_0;
  const v8d g145_1 = q7*g44_1 - p44*e7;
  const v8d g146_0 = q7*g45_0;
  const v8d g146_1 = q7*g45_1 - p45*e7;
  const v8d g147_0 = q6*g45_0;
  const v8d g147_1 = q6*g45_1 - p45*e6;
  const v8d g148_0 = q7*g46_0;
  const v8d g148_1 = q7*g46_1 - p46*e7;
  const v8d g149_0 = q6*g46_0;
  const v8d g149_1 = q6*g46_1 - p46*e6;
  const v8d g150_0 = q5*g46_0 - p46*e5;
  const v8d g150_1 = q5*g46_1;
  const v8d g151_0 = q7*g47_0;
  const v8d g151_1 = q7*g47_1 - p47*e7;
  const v8d g152_0 = q6*g47_0;
  const v8d g152_1 = q6*g47_1 - p47*e6;
  const v8d g153_0 = q5*g47_0 - p47*e5;
  const v8d g153_1 = q5*g47_1;
  const v8d g154_0 = q4*g47_0 - p47*e4;
  const v8d g154_1 = q4*g47_1;
  const v8d g155_0 = q8*g48_0;
  const v8d g155_1 = q8*g48_1 - p48*e8;
  const v8d g156_0 = q7*g48_0;
  const v8d g156_1 = q7*g48_1 - p48*e7;
  const v8d g157_0 = q6*g48_0;
  const v8d g157_1 = q6*g48_1 - p48*e6;
  const v8d g158_0 = q5*g48_0 - p48*e5;
  const v8d g158_1 = q5*g48_1;
  const v8d g159_0 = q4*g48_0 - p48*e4;
  const v8d g159_1 = q4*g48_1;
  const v8d g160_0 = q3*g48_0 - p48*e3;
  const v8d g160_1 = q3*g48_1;
  const v8d g161_0 = q8*g49_0;
  const v8d g161_1 = q8*g49_1 - p49*e8;
  const v8d g162_0 = q7*g49_0;
  const v8d g162_1 = q7*g49_1 - p49*e7;
  const v8d g163_0 = q6*g49_0;
  const v8d g163_1 = q6*g49_1 - p49*e6;
  const v8d g164_0 = q5*g49_0 - p49*e5;
  const v8d g164_1 = q5*g49_1;
  const v8d g165_0 = q4*g49_0 - p49*e4;
  const v8d g165_1 = q4*g49_1;
  const v8d g166_0 = q3*g49_0 - p49*e3;
  const v8d g166_1 = q3*g49_1;
  const v8d g167_0 = q2*g49_0 - p49*e2;
  const v8d g167_1 = q2*g49_1;
  const v8d g168_0 = q7*g50_0;
  const v8d g168_1 = q7*g50_1 - p50*e7;
  const v8d g169_0 = q5*g50_0 - p50*e5;
  const v8d g169_1 = q5*g50_1;
  const v8d g170_0 = q4*g50_0 - p50*e4;
  const v8d g170_1 = q4*g50_1;
  const v8d g171_0 = q3*g50_0 - p50*e3;
  const v8d g171_1 = q3*g50_1;
  const v8d g172_0 = q2*g50_0 - p50*e2;
  const v8d g172_1 = q2*g50_1;
  const v8d g173_0 = q1*g50_0 - p50*e1;
  const v8d g173_1 = q1*g50_1;
  const v8d g174_0 = q8*g52_0;
  const v8d g174_1 = q8*g52_1 - p52*e8;
  const v8d g175_0 = q7*g52_0;
  const v8d g175_1 = q7*g52_1 - p52*e7;
  const v8d g176_0 = q8*g53_0;
  const v8d g176_1 = q8*g53_1 - p53*e8;
  const v8d g177_0 = q6*g54_0;
  const v8d g177_1 = q6*g54_1 - p54*e6;
  const v8d g178_0 = q5*g54_0 - p54*e5;
  const v8d g178_1 = q5*g54_1;
  const v8d g179_0 = q8*g55_0;
  const v8d g179_1 = q8*g55_1 - p55*e8;
  const v8d g180_0 = q7*g55_0;
  const v8d g180_1 = q7*g55_1 - p55*e7;
  const v8d g181_0 = q6*g55_0;
  const v8d g181_1 = q6*g55_1 - p55*e6;
  const v8d g182_0 = q5*g55_0 - p55*e5;
  const v8d g182_1 = q5*g55_1;
  const v8d g183_0 = q4*g55_0 - p55*e4;
  const v8d g183_1 = q4*g55_1;
  const v8d g184_0 = q7*g56_0;
  const v8d g184_1 = q7*g56_1 - p56*e7;
  const v8d g185_0 = q6*g56_0;
  const v8d g185_1 = q6*g56_1 - p56*e6;
  const v8d g186_0 = q5*g56_0 - p56*e5;
  const v8d g186_1 = q5*g56_1;
  const v8d g187_0 = q4*g56_0 - p56*e4;
  const v8d g187_1 = q4*g56_1;
  const v8d g188_0 = q3*g56_0 - p56*e3;
  const v8d g188_1 = q3*g56_1;
  const v8d g189_0 = q8*g57_0;
  const v8d g189_1 = q8*g57_1 - p57*e8;
  const v8d g190_0 = q7*g57_0;
  const v8d g190_1 = q7*g57_1 - p57*e7;
  const v8d g191_0 = q6*g57_0;
  const v8d g191_1 = q6*g57_1 - p57*e6;
  const v8d g192_0 = q5*g57_0 - p57*e5;
  const v8d g192_1 = q5*g57_1;
  const v8d g193_0 = q4*g57_0 - p57*e4;
  const v8d g193_1 = q4*g57_1;
  const v8d g194_0 = q3*g57_0 - p57*e3;
  const v8d g194_1 = q3*g57_1;
  const v8d g195_0 = q2*g57_0 - p57*e2;
  const v8d g195_1 = q2*g57_1;
  const v8d g196_0 = q7*g58_0;
  const v8d g196_1 = q7*g58_1 - p58*e7;
  const v8d g197_0 = q6*g58_0;
  const v8d g197_1 = q6*g58_1 - p58*e6;
  const v8d g198_0 = q5*g58_0 - p58*e5;
  const v8d g198_1 = q5*g58_1;
  const v8d g199_0 = q4*g58_0 - p58*e4;
  const v8d g199_1 = q4*g58_1;
  const v8d g200_0 = q3*g58_0 - p58*e3;
  const v8d g200_1 = q3*g58_1;
  const v8d g201_0 = q2*g58_0 - p58*e2;
  const v8d g201_1 = q2*g58_1;
  const v8d g202_0 = q1*g58_0 - p58*e1;
  const v8d g202_1 = q1*g58_1;
  const v8d g203_0 = q7*g59_0;
  const v8d g203_1 = q7*g59_1 - p59*e7;
  const v8d g204_0 = q5*g59_0 - p59*e5;
  const v8d g204_1 = q5*g59_1;
  const v8d g205_0 = q4*g59_0 - p59*e4;
  const v8d g205_1 = q4*g59_1;
  const v8d g206_0 = q3*g59_0 - p59*e3;
  const v8d g206_1 = q3*g59_1;
  const v8d g207_0 = q2*g59_0 - p59*e2;
  const v8d g207_1 = q2*g59_1;
  const v8d g208_0 = q1*g59_0 - p59*e1;
  const v8d g208_1 = q1*g59_1;
  const double p209 = q0*p59;
  const v8d g209_0 = q0*g59_0 - p59*e0;
  const v8d g209_1 = q0*g59_1;
  const double p210 = q10*p60;
  const v8d g210_0 = q10*g60_0;
  const v8d g210_1 = q10*g60_1 - p60*e10;
  const double p211 = q10*p61;
  const v8d g211_0 = q10*g61_0;
  const v8d g211_1 = q10*g61_1 - p61*e10;
  const double p212 = q10*p62;
  const v8d g212_0 = q10*g62_0;
  const v8d g212_1 = q10*g62_1 - p62*e10;
  const double p213 = q10*p63;
  const v8d g213_0 = q10*g63_0;
  const v8d g213_1 = q10*g63_1 - p63*e10;
  const double p214 = q9*p63;
  const v8d g214_0 = q9*g63_0;
  const v8d g214_1 = q9*g63_1 - p63*e9;
  const v8d g215_0 = q9*g64_0;
  const v8d g215_1 = q9*g64_1 - p64*e9;
  const double p216 = q8*p66;
  const v8d g216_0 = q8*g66_0;
  const v8d g216_1 = q8*g66_1 - p66*e8;
  const double p217 = q8*p67;
  const v8d g217_0 = q8*g67_0;
  const v8d g217_1 = q8*g67_1 - p67*e8;
  const double p218 = q8*p68;
  const v8d g218_0 = q8*g68_0;
  const v8d g218_1 = q8*g68_1 - p68*e8;
  const double p219 = q8*p69;
  const v8d g219_0 = q8*g69_0;
  const v8d g219_1 = q8*g69_1 - p69*e8;
  const double p220 = q7*p69;
  const v8d g220_0 = q7*g69_0;
  const v8d g220_1 = q7*g69_1 - p69*e7;
  const double p221 = q8*p70;
  const v8d g221_0 = q8*g70_0;
  const v8d g221_1 = q8*g70_1 - p70*e8;
  const double p222 = q8*p71;
  const v8d g222_0 = q8*g71_0;
  const v8d g222_1 = q8*g71_1 - p71*e8;
  const double p223 = q8*p72;
  const v8d g223_0 = q8*g72_0;
  const v8d g223_1 = q8*g72_1 - p72*e8;
  const double p224 = q7*p72;
  const v8d g224_0 = q7*g72_0;
  const v8d g224_1 = q7*g72_1 - p72*e7;
  const double p225 = q8*p73;
  const v8d g225_0 = q8*g73_0;
  const v8d g225_1 = q8*g73_1 - p73*e8;
  const double p226 = q8*p74;
  const v8d g226_0 = q8*g74_0;
  const v8d g226_1 = q8*g74_1 - p74*e8;
  const double p227 = q7*p74;
  const v8d g227_0 = q7*g74_0;
  const v8d g227_1 = q7*g74_1 - p74*e7;
  const double p228 = q8*p75;
  const v8d g228_0 = q8*g75_0;
  const v8d g228_1 = q8*g75_1 - p75*e8;
  const double p229 = q7*p75;
  const v8d g229_0 = q7*g75_0;
  const v8d g229_1 = q7*g75_1 - p75*e7;
  const double p230 = q6*p75;
  const v8d g230_0 = q6*g75_0;
  const v8d g230_1 = q6*g75_1 - p75*e6;
  const double p231 = q2*p143;
  const v8d g231_0 = q2*g143_0 - p143*e2;
  const v8d g231_1 = q2*g143_1;
  const double p232 = q1*p209;
  const v8d g232_0 = q1*g209_0 - p209*e1;
  const v8d g232_1 = q1*g209_1;
  const double p233 = q0*p209;
  const v8d g233_0 = q0*g209_0 - p209*e0;
  const v8d g233_1 = q0*g209_1;
  const double p234 = q10*p210;
  const v8d g234_0 = q10*g210_0;
  const v8d g234_1 = q10*g210_1 - p210*e10;
  const double p235 = q10*p211;
  const v8d g235_0 = q10*g211_0;
  const v8d g235_1 = q10*g211_1 - p211*e10;
  const double p236 = q10*p212;
  const v8d g236_0 = q10*g212_0;
  const v8d g236_1 = q10*g212_1 - p212*e10;
  const double p237 = q10*p213;
  const v8d g237_0 = q10*g213_0;
  const v8d g237_1 = q10*g213_1 - p213*e10;
  const double p238 = q9*p214;
  const v8d g238_0 = q9*g214_0;
  const v8d g238_1 = q9*g214_1 - p214*e9;
  const double p239 = q8*p216;
  const v8d g239_0 = q8*g216_0;
  const v8d g239_1 = q8*g216_1 - p216*e8;
  const v8d g240_0 = q8*g217_0;
  const v8d g240_1 = q8*g217_1 - p217*e8;
  const v8d g241_0 = q8*g218_0;
  const v8d g241_1 = q8*g218_1 - p218*e8;
  const double p242 = q8*p219;
  const v8d g242_0 = q8*g219_0;
  const v8d g242_1 = q8*g219_1 - p219*e8;
  const double p243 = q8*p220;
  const v8d g243_0 = q8*g220_0;
  const v8d g243_1 = q8*g220_1 - p220*e8;
  const double p244 = q7*p220;
  const v8d g244_0 = q7*g220_0;
  const v8d g244_1 = q7*g220_1 - p220*e7;
  const double p245 = q8*p221;
  const v8d g245_0 = q8*g221_0;
  const v8d g245_1 = q8*g221_1 - p221*e8;
  const double p246 = q8*p222;
  const v8d g246_0 = q8*g222_0;
  const v8d g246_1 = q8*g222_1 - p222*e8;
  const double p247 = q8*p223;
  const v8d g247_0 = q8*g223_0;
  const v8d g247_1 = q8*g223_1 - p223*e8;
  const double p248 = q8*p224;
  const v8d g248_0 = q8*g224_0;
  const v8d g248_1 = q8*g224_1 - p224*e8;
  const double p249 = q7*p224;
  const v8d g249_0 = q7*g224_0;
  const v8d g249_1 = q7*g224_1 - p224*e7;
  const double p250 = q8*p225;
  const v8d g250_0 = q8*g225_0;
  const v8d g250_1 = q8*g225_1 - p225*e8;
  const double p251 = q8*p226;
  const v8d g251_0 = q8*g226_0;
  const v8d g251_1 = q8*g226_1 - p226*e8;
  const double p252 = q8*p227;
  const v8d g252_0 = q8*g227_0;
  const v8d g252_1 = q8*g227_1 - p227*e8;
  const double p253 = q7*p227;
  const v8d g253_0 = q7*g227_0;
  const v8d g253_1 = q7*g227_1 - p227*e7;
  const double p254 = q8*p228;
  const v8d g254_0 = q8*g228_0;
  const v8d g254_1 = q8*g228_1 - p228*e8;
  const double p255 = q8*p229;
  const v8d g255_0 = q8*g229_0;
  const v8d g255_1 = q8*g229_1 - p229*e8;
  const double p256 = q7*p229;
  const v8d g256_0 = q7*g229_0;
  const v8d g256_1 = q7*g229_1 - p229*e7;
  const double p257 = q8*p230;
  const v8d g257_0 = q8*g230_0;
  const v8d g257_1 = q8*g230_1 - p230*e8;
  const double p258 = q7*p230;
  const v8d g258_0 = q7*g230_0;
  const v8d g258_1 = q7*g230_1 - p230*e7;
  const double p259 = q6*p230;
  const v8d g259_0 = q6*g230_0;
  const v8d g259_1 = q6*g230_1 - p230*e6;
  const v8d g260_0 = q2*g231_0 - p231*e2;
  const v8d g260_1 = q2*g231_1;
  const v8d g261_0 = q1*g232_0 - p232*e1;
  const v8d g261_1 = q1*g232_1;
  const double p262 = q1*p233;
  const v8d g262_0 = q1*g233_0 - p233*e1;
  const v8d g262_1 = q1*g233_1;
  const double p263 = q0*p233;
  const v8d g263_0 = q0*g233_0 - p233*e0;
  const v8d g263_1 = q0*g233_1;
  const double p264 = q10*p234;
  const v8d g264_0 = q10*g234_0;
  const v8d g264_1 = q10*g234_1 - p234*e10;
  const double p265 = q10*p235;
  const v8d g265_0 = q10*g235_0;
  const v8d g265_1 = q10*g235_1 - p235*e10;
  const double p266 = q10*p236;
  const v8d g266_0 = q10*g236_0;
  const v8d g266_1 = q10*g236_1 - p236*e10;
  const double p267 = q10*p237;
  const v8d g267_0 = q10*g237_0;
  const v8d g267_1 = q10*g237_1 - p237*e10;
  const double p268 = q10*p238;
  const v8d g268_0 = q10*g238_0;
  const v8d g268_1 = q10*g238_1 - p238*e10;
  const double p269 = q9*p238;
  const v8d g269_0 = q9*g238_0;
  const v8d g269_1 = q9*g238_1 - p238*e9;
  const v8d g270_0 = q8*g239_0;
  const v8d g270_1 = q8*g239_1 - p239*e8;
  const v8d g271_0 = q8*g242_0;
  const v8d g271_1 = q8*g242_1 - p242*e8;
  const v8d g272_0 = q8*g243_0;
  const v8d g272_1 = q8*g243_1 - p243*e8;
  const v8d g273_0 = q8*g244_0;
  const v8d g273_1 = q8*g244_1 - p244*e8;
  const v8d g274_0 = q7*g244_0;
  const v8d g274_1 = q7*g244_1 - p244*e7;
  const v8d g275_0 = q8*g245_0;
  const v8d g275_1 = q8*g245_1 - p245*e8;
  const v8d g276_0 = q8*g246_0;
  const v8d g276_1 = q8*g246_1 - p246*e8;
  const v8d g277_0 = q8*g247_0;
  const v8d g277_1 = q8*g247_1 - p247*e8;
  const v8d g278_0 = q8*g248_0;
  const v8d g278_1 = q8*g248_1 - p248*e8;
  const v8d g279_0 = q8*g249_0;
  const v8d g279_1 = q8*g249_1 - p249*e8;
  const v8d g280_0 = q7*g249_0;
  const v8d g280_1 = q7*g249_1 - p249*e7;
  const v8d g281_0 = q8*g250_0;
  const v8d g281_1 = q8*g250_1 - p250*e8;
  const v8d g282_0 = q8*g251_0;
  const v8d g282_1 = q8*g251_1 - p251*e8;
  const v8d g283_0 = q8*g252_0;
  const v8d g283_1 = q8*g252_1 - p252*e8;
  const v8d g284_0 = q8*g253_0;
  const v8d g284_1 = q8*g253_1 - p253*e8;
  const v8d g285_0 = q7*g253_0;
  const v8d g285_1 = q7*g253_1 - p253*e7;
  const v8d g286_0 = q8*g254_0;
  const v8d g286_1 = q8*g254_1 - p254*e8;
  const v8d g287_0 = q8*g255_0;
  const v8d g287_1 = q8*g255_1 - p255*e8;
  const v8d g288_0 = q8*g256_0;
  const v8d g288_1 = q8*g256_1 - p256*e8;
  const v8d g289_0 = q7*g256_0;
  const v8d g289_1 = q7*g256_1 - p256*e7;
  const v8d g290_0 = q8*g257_0;
  const v8d g290_1 = q8*g257_1 - p257*e8;
  const v8d g291_0 = q8*g258_0;
  const v8d g291_1 = q8*g258_1 - p258*e8;
  const v8d g292_0 = q7*g258_0;
  const v8d g292_1 = q7*g258_1 - p258*e7;
  const v8d g293_0 = q8*g259_0;
  const v8d g293_1 = q8*g259_1 - p259*e8;
  const v8d g294_0 = q7*g259_0;
  const v8d g294_1 = q7*g259_1 - p259*e7;
  const v8d g295_0 = q6*g259_0;
  const v8d g295_1 = q6*g259_1 - p259*e6;
  const v8d g296_0 = q1*g262_0 - p262*e1;
  const v8d g296_1 = q1*g262_1;
  const v8d g297_0 = q1*g263_0 - p263*e1;
  const v8d g297_1 = q1*g263_1;
  const v8d g298_0 = q0*g263_0 - p263*e0;
  const v8d g298_1 = q0*g263_1;
  const double p299 = q10*p264;
  const v8d g299_0 = q10*g264_0;
  const v8d g299_1 = q10*g264_1 - p264*e10;
  const v8d g300_0 = q10*g265_0;
  const v8d g300_1 = q10*g265_1 - p265*e10;
  const v8d g301_0 = q10*g266_0;
  const v8d g301_1 = q10*g266_1 - p266*e10;
  const v8d g302_0 = q10*g267_0;
  const v8d g302_1 = q10*g267_1 - p267*e10;
  const v8d g303_0 = q10*g268_0;
  const v8d g303_1 = q10*g268_1 - p268*e10;
  const double p304 = q9*p269;
  const v8d g304_0 = q9*g269_0;
  const v8d g304_1 = q9*g269_1 - p269*e9;
  const double p305 = q10*p299;
  const v8d g305_0 = q10*g299_0;
  const v8d g305_1 = q10*g299_1 - p299*e10;
  const double p306 = q9*p304;
  const v8d g306_0 = q9*g304_0;
  const v8d g306_1 = q9*g304_1 - p304*e9;
  const v8d g307_0 = q10*g305_0;
  const v8d g307_1 = q10*g305_1 - p305*e10;
  const v8d g308_0 = q9*g306_0;
  const v8d g308_1 = q9*g306_1 - p306*e9;
  { const v8d a0 = (0.2226839703329741*g_one_0 + -0.18276085629856928*g48_0 + 0.13300649061232131*g160_0) + (0.1073805083448367*g10_0 + -0.072593777252058386*g34_0 + 0.083558875264861804*g119_0);
    std::memcpy(moment_arm + 0, &a0, 6 * sizeof(double)); std::memset(moment_arm + 6, 0, 5 * sizeof(double)); L[0] = a0[6]; }
  { const v8d a0 = (0.21245884539662985*g_one_0 + 0.11896035630523864*g10_0 + -0.0071317343858427638*g132_0 + 0.021024278068381322*g142_0) + (0.0065113377739097027*g208_0 + -0.062953962053257595*g9_0 + -0.05088986782450889*g183_0);
    std::memcpy(moment_arm + 11, &a0, 6 * sizeof(double)); std::memset(moment_arm + 17, 0, 5 * sizeof(double)); L[1] = a0[6]; }
  { const v8d a0 = (0.18307973897400198*g_one_0 + -0.061503856261289958*g9_0 + -0.00058665176749715556*g48_0 + 0.042941637847571081*g137_0 + -0.042508825696147522*g170_0) + (0.11121775011631051*g10_0 + 0.049272676689420793*g136_0 + -0.042206925373611488*g99_0 + -0.037467327306776335*g192_0 + 0.012001932329573554*g42_0);
    std::memcpy(moment_arm + 22, &a0, 6 * sizeof(double)); std::memset(moment_arm + 28, 0, 5 * sizeof(double)); L[2] = a0[6]; }
  { const v8d a0 = (0.17019370080997737*g_one_0 + -0.049505378727816643*g9_0 + 0.044373715931776067*g137_0 + -0.085342991012893069*g132_0 + 0.010900121572822226*g143_0) + (0.12125774522303981*g10_0 + 0.013211082195623603*g187_0 + -0.06332403372429464*g99_0 + 0.0081882664437248533*g118_0);
    std::memcpy(moment_arm + 33, &a0, 6 * sizeof(double)); std::memset(moment_arm + 39, 0, 5 * sizeof(double)); L[3] = a0[6]; }
  { const v8d a0 = (0.16115600592066501*g_one_0 + 0.088320070404495021*g9_0 + 0.29327146529456966*g160_0 + 0.030135841057041302*g143_0 + -0.39038654272599593*g48_0 + 0.015230706606506748*g137_0) + (0.12061876608700683*g10_0 + 0.013127094703938694*g114_0 + -0.066994059146322907*g99_0 + -0.21769654260387308*g131_0 + 0.11360527071051553*g128_0 + -0.042800483159235361*g170_0);
    std::memcpy(moment_arm + 44, &a0, 6 * sizeof(double)); std::memset(moment_arm + 50, 0, 5 * sizeof(double)); L[4] = a0[6]; }
  { const v8d a0 = (0.16490802105943925*g_one_0 + -0.029009744211328705*g34_0 + 0.015228683468617795*g142_0 + 0.039203217864049095*g137_0) + (0.1279263754629717*g10_0 + 0.12375701424527387*g136_0 + 0.041141832960783088*g29_0);
    std::memcpy(moment_arm + 55, &a0, 6 * sizeof(double)); std::memset(moment_arm + 61, 0, 5 * sizeof(double)); L[5] = a0[6]; }
  { const v8d a0 = (0.17057972229140822*g_one_0 + 0.17199870819960481*g199_0 + -0.0025467458204471577*g99_0 + -0.050129518188046722*g201_0 + 0.08645607786729996*g29_0 + -0.014573377282186006*g114_0 + -0.076945367132192952*g5_0) + (0.11736101552148655*g10_0 + 0.061364175811538843*g57_0 + -0.15758884123468345*g118_0 + -0.10442325438138389*g132_0 + 0.029836356664026918*g171_0 + 0.22998529512543628*g33_0);
    std::memcpy(moment_arm + 66, &a0, 6 * sizeof(double)); std::memset(moment_arm + 72, 0, 5 * sizeof(double)); L[6] = a0[6]; }
  { const v8d a0 = (0.16350597096075056*g_one_0 + 0.030708068950944887*g154_0 + -0.09208039288296499*g183_0 + -0.064092764144549202*g6_0 + -0.097300067664169321*g200_0 + -0.080224779432267065*g187_0 + 0.070079223378816752*g207_0) + (0.10791933111566702*g10_0 + 0.084636678807819082*g40_0 + -0.018047725719688781*g202_0 + 0.034744591619896265*g9_0 + 0.089269526946695266*g57_0 + -0.057190904851229886*g141_0 + 0.0035642541863898963*g120_0);
    std::memcpy(moment_arm + 77, &a0, 6 * sizeof(double)); std::memset(moment_arm + 83, 0, 5 * sizeof(double)); L[7] = a0[6]; }
  { const v8d a0 = (0.16407852009792581*g_one_0 + 0.11728876240167255*g194_0 + -0.11633320157634924*g6_0 + 0.21584983155379153*g40_0 + 0.0585855719714082*g9_0 + 0.11771695918059356*g208_0 + 0.21619642906704864*g132_0 + -0.057137156345473457*g114_0 + 0.04827176942630123*g207_0) + (0.01197970875261376*g154_0 + 0.029533712713908217*g160_0 + -0.15551598056645785*g188_0 + -0.072498768805458788*g55_0 + 0.24318249363676989*g56_0 + 0.015397251589343512*g118_0 + 0.15305384044813169*g187_0 + 0.020531073006684022*g143_0);
    std::memcpy(moment_arm + 88, &a0, 6 * sizeof(double)); std::memset(moment_arm + 94, 0, 5 * sizeof(double)); L[8] = a0[6]; }
  { const v8d a0 = (0.18628696522460711*g_one_0 + 0.18157667147627637*g57_0 + 0.080751377445309844*g9_0 + -0.12064752253785191*g200_0 + 0.21603882070209732*g56_0 + 0.10127685319101404*g136_0) + (0.0063275340892183099*g47_0 + -0.09076532917939785*g6_0 + 0.043596281950511434*g187_0 + -0.016165250333250836*g173_0 + -0.1440618893570936*g188_0 + 0.1714380728840173*g207_0);
    std::memcpy(moment_arm + 99, &a0, 6 * sizeof(double)); std::memset(moment_arm + 105, 0, 5 * sizeof(double)); L[9] = a0[6]; }
  { const v8d a0 = (0.22866775617826396*g_one_0 + 0.015171676961334592*g57_0 + 0.018845847929431305*g171_0 + 0.056499231348319336*g201_0 + 0.011135949116275161*g188_0 + -0.052856507227115844*g119_0 + 0.041809280595352341*g99_0 + -0.19661302437722031*g113_0 + 0.087511274740108308*g10_0 + 0.036236557731154063*g59_0) + (-0.028670128598098268*g47_0 + 0.12461338761637003*g98_0 + 0.17505193900064525*g28_0 + 0.10144586921785897*g170_0 + 0.054166421815637952*g49_0 + 0.08017698690867088*g9_0 + -0.065586705599447043*g58_0 + 0.018244064951454281*g136_0 + -0.064352752897807022*g8_0 + 0.11727353894716203*g29_0);
    std::memcpy(moment_arm + 110, &a0, 6 * sizeof(double)); std::memset(moment_arm + 116, 0, 5 * sizeof(double)); L[10] = a0[6]; }
  { const v8d a0 = (0.19987178549542378*g_one_0 + -0.46698425924904752*g298_0 + 1.6734656022784056*g263_0 + 2.6611618537189718*g233_0 + 0.030785617802033424*g260_0) + (0.941960000730655*g58_0 + -10.085981965305807*g297_0 + -9.5171850549514083*g262_0 + 2.5804681024444589*g208_0 + 1.0698352594554734*g209_0);
    std::memcpy(moment_arm + 121, &a0, 6 * sizeof(double)); std::memset(moment_arm + 127, 0, 5 * sizeof(double)); L[11] = a0[6]; }
  { const v8d a0 = (0.19296653545254419*g_one_0 + 1.3082683443775576*g209_0 + 0.032434643716740048*g261_0 + -17.340360909931178*g297_0 + 0.24411354514020278*g296_0 + 2.3702171687922462*g263_0 + 0.0085214960364174714*g42_0) + (0.53015918475987078*g58_0 + -21.739945358570065*g262_0 + -0.28763769421997887*g298_0 + -0.0086438534512877831*g8_0 + 0.0061664020194029208*g173_0 + -7.9945817943417437*g232_0 + 3.3489581817726863*g233_0);
    std::memcpy(moment_arm + 132, &a0, 6 * sizeof(double)); std::memset(moment_arm + 138, 0, 5 * sizeof(double)); L[12] = a0[6]; }
  { const v8d a0 = (0.17285010137551521*g_one_0 + -0.1731654228580424*g137_0 + -0.099844302717647507*g9_0 + 0.26409536383432719*g41_0 + 0.10036936156488532*g6_0 + -0.034682214552087663*g170_0 + 0.021487733053100484*g153_0) + (0.046942701140040136*g47_0 + 0.03970150033225299*g114_0 + 0.025803348563775693*g186_0 + -0.068166874415907061*g7_0 + -0.0091071952557205318*g8_0 + 0.089052361375231023*g35_0);
    std::memcpy(moment_arm + 143, &a0, 6 * sizeof(double)); std::memset(moment_arm + 149, 0, 5 * sizeof(double)); L[13] = a0[6]; }
  { const v8d a0 = (0.10369029144934436*g_one_0 + -0.18857127459059703*g137_0 + -0.051268330625507709*g171_0 + -0.075522744371284617*g170_0 + 0.33533695748676012*g41_0 + 0.073826435753550537*g119_0 + 0.032343760021199042*g49_0 + -0.068540849929930495*g8_0) + (0.11052762001483615*g47_0 + -0.059367847405468681*g205_0 + -0.0077828963338926931*g183_0 + -0.01372382706591496*g118_0 + 0.055124847848510496*g35_0 + -0.07976535203194382*g9_0 + -0.076444512162525693*g55_0);
    std::memcpy(moment_arm + 154, &a0, 6 * sizeof(double)); std::memset(moment_arm + 160, 0, 5 * sizeof(double)); L[14] = a0[6]; }
  { const v8d a0 = (0.12515869664574622*g_one_0 + 0.01164799614340044*g109_0 + 0.0010314191336629119*g170_0 + 0.018788957685093342*g46_0 + 0.017760386041553465*g132_0 + 0.077585837301978933*g9_0 + -0.040313168133524015*g7_0 + 0.022081735265894516*g114_0 + -0.022124343558405316*g188_0) + (0.0052502771115715222*g58_0 + -0.086917497612268885*g118_0 + -0.014019441094647343*g209_0 + 0.017356005380804236*g208_0 + 0.072962446478012033*g200_0 + -0.028259469612597024*g10_0 + 0.11314516124996545*g33_0 + -0.030585748824701338*g201_0 + 0.02081730240384097*g98_0);
    std::memcpy(moment_arm + 165, &a0, 6 * sizeof(double)); std::memset(moment_arm + 171, 0, 5 * sizeof(double)); L[15] = a0[6]; }
  { const v8d a0 = (0.10886744353755116*g_one_0 + 0.10854559928961179*g33_0 + 0.021034887514961284*g192_0 + 0.077214506840085184*g188_0 + -0.11829486564415294*g56_0 + -0.059900326086259399*g199_0 + 0.03197749356829617*g169_0 + 0.017387698380067672*g140_0 + 0.026691885643530991*g200_0 + 0.01988210987312158*g34_0 + -0.0088491464280197104*g40_0) + (0.11441360234656921*g9_0 + -0.036004809385256742*g205_0 + -0.037135351442955891*g160_0 + -0.039881768124536567*g6_0 + -0.0088739793128490719*g135_0 + -0.041419502048979713*g113_0 + -0.038572987542029438*g165_0 + -0.028353969226706209*g187_0 + -0.069215762733545919*g118_0 + 0.021416677926053899*g170_0);
    std::memcpy(moment_arm + 176, &a0, 6 * sizeof(double)); std::memset(moment_arm + 182, 0, 5 * sizeof(double)); L[16] = a0[6]; }
  { const v8d a0 = (0.085363255651111525*g_one_0 + 0.077473602495008689*g33_0 + -0.021562674030823657*g194_0 + -0.058185626893730101*g160_0 + 0.098542544734225093*g200_0 + -0.033998932921435646*g10_0 + 0.12513573484626819*g46_0) + (0.15901620947862294*g9_0 + -0.049395149176513546*g205_0 + -0.14846625732484819*g158_0 + -0.029376622593829265*g188_0 + -0.01088377119342588*g40_0 + 0.018836596897869404*g114_0);
    std::memcpy(moment_arm + 187, &a0, 6 * sizeof(double)); std::memset(moment_arm + 193, 0, 5 * sizeof(double)); L[17] = a0[6]; }
  { const v8d a0 = (0.10432667636646144*g_one_0 + 0.065108144046768457*g33_0 + 0.048879525076745214*g186_0 + -0.052905879518361155*g160_0 + -0.070453104725712826*g208_0 + 0.047350026958477294*g170_0 + 0.050894580449069041*g59_0) + (0.14509764387402749*g9_0 + -0.0073826315364101652*g205_0 + 0.0055010920401078033*g8_0 + -0.015731727066031466*g56_0 + 0.024591773951400168*g167_0 + -0.012869622353361832*g6_0 + 0.019711820048375298*g5_0);
    std::memcpy(moment_arm + 198, &a0, 6 * sizeof(double)); std::memset(moment_arm + 204, 0, 5 * sizeof(double)); L[18] = a0[6]; }
  { const v8d a0 = (0.13845316452834452*g_one_0 + 0.027676424994641353*g137_0 + 0.053473480407535016*g47_0 + -0.0067689615632594395*g173_0 + 0.1037692370539721*g154_0 + -0.065151312547680543*g195_0 + -0.18584000009561999*g132_0 + 0.026799493858875471*g120_0 + -0.11005288942084759*g99_0 + -0.034934374105751217*g140_0 + -0.069665932204688141*g136_0) + (-0.10754852382302041*g199_0 + 0.093174194898537663*g10_0 + 0.0060991791741942195*g153_0 + 0.060089623654047505*g6_0 + 0.030999275798038795*g206_0 + -0.0096816953714176403*g118_0 + 0.03862412845874065*g8_0 + -0.0069738698615569835*g170_0 + -0.061852364292139847*g9_0 + -0.044433853162650631*g187_0);
    std::memcpy(moment_arm + 209, &a0, 6 * sizeof(double)); std::memset(moment_arm + 215, 0, 5 * sizeof(double)); L[19] = a0[6]; }
  { const v8d a0 = (0.13910857175965552*g_one_0 + 0.016011317074464047*g41_0 + -0.068555600801733341*g118_0 + 0.0055002054971630939*g186_0 + -0.33037573292838734*g55_0 + 0.033464678477062214*g193_0 + -0.13073233522296751*g205_0 + -0.11727009528390558*g99_0 + 0.084454132319181252*g8_0 + 0.088768346427285594*g47_0) + (-0.2168398021775389*g183_0 + 0.21793072357495616*g199_0 + -0.2257627598956545*g29_0 + -0.013830799713046306*g171_0 + 0.075628849525808367*g114_0 + 0.039203560052230656*g158_0 + 0.15084982659079629*g58_0 + 0.032785502978476572*g198_0 + 0.030450861212480668*g35_0);
    std::memcpy(moment_arm + 220, &a0, 6 * sizeof(double)); std::memset(moment_arm + 226, 0, 5 * sizeof(double)); L[20] = a0[6]; }
  { const v8d a0 = (0.11552925677750556*g_one_0 + 0.25588101648244449*g41_0 + -0.072459781469791693*g186_0 + -0.16453058991608543*g137_0 + 0.020164615435920231*g200_0 + 0.064466260892791602*g208_0 + 0.18867836536308003*g56_0 + -0.069152345031935861*g118_0 + 0.052176232081937966*g193_0 + -0.13854839991361687*g205_0) + (0.17459940338756252*g183_0 + -0.078094142715750173*g199_0 + 0.067211256661449573*g7_0 + 0.038138315069648841*g119_0 + -0.13859415498147204*g188_0 + 0.13448429786579771*g6_0 + 0.08545444238632055*g58_0 + -0.10174851001479468*g182_0 + 0.086349209637399713*g114_0 + -0.042270295754168651*g48_0);
    std::memcpy(moment_arm + 231, &a0, 6 * sizeof(double)); std::memset(moment_arm + 237, 0, 5 * sizeof(double)); L[21] = a0[6]; }
  { const v8d a0 = (0.097691259093350802*g_one_0 + 0.085263368466312259*g41_0 + -0.060607726353751161*g118_0 + -0.13182926602117881*g205_0 + 0.01902362051055655*g158_0 + 0.062920129182620882*g7_0 + 0.16783486412575205*g200_0 + -0.15024096050742433*g59_0) + (-0.14091845174243728*g55_0 + -0.044731631656129298*g154_0 + -0.039908857804088052*g201_0 + -0.14593691630315633*g209_0 + -0.042959980796184905*g137_0 + 0.10503896310872464*g6_0 + -0.048542443062506622*g98_0 + 0.063952584674449711*g8_0);
    std::memcpy(moment_arm + 242, &a0, 6 * sizeof(double)); std::memset(moment_arm + 248, 0, 5 * sizeof(double)); L[22] = a0[6]; }
  { const v8d a0 = (0.11755871570509976*g_one_0 + -0.03638432450787657*g41_0 + -0.026370006489015524*g201_0 + 0.037138528565468121*g137_0 + -0.006870690906345899*g172_0 + 0.027960800184060376*g48_0 + -0.059898789580771696*g199_0 + -0.081745232012674252*g118_0 + -0.030118085202586239*g209_0 + -0.067614230008747736*g195_0 + 0.16762631761161986*g6_0 + -0.055077126830630138*g202_0 + -0.10709688768317034*g98_0) + (-0.11810569129285271*g55_0 + 0.037650077146068738*g204_0 + 0.033067799644209243*g7_0 + 0.020443172796195504*g136_0 + 0.21139085491100995*g200_0 + -0.01831938497911224*g159_0 + -0.064700834167626731*g34_0 + -0.11890121002200106*g205_0 + 0.046848091618648398*g164_0 + -0.04891936120122347*g113_0 + 0.072486391056279575*g10_0 + 0.10808168803764058*g8_0);
    std::memcpy(moment_arm + 253, &a0, 6 * sizeof(double)); std::memset(moment_arm + 259, 0, 5 * sizeof(double)); L[23] = a0[6]; }
  { const v8d a0 = (0.12134023964586003*g_one_0 + -0.15961926658209125*g8_0 + 0.16969536517200462*g132_0 + 0.080643519927238227*g173_0 + -0.14590416510646873*g6_0 + 0.04044254537231301*g171_0 + 0.0048766603236754576*g182_0 + 0.15275225902384992*g141_0 + 0.16294608027416835*g198_0 + 0.14225906781815534*g200_0 + -0.038090823263556416*g188_0 + 0.14349106385265181*g98_0) + (-0.018385617479422821*g55_0 + -0.021420743231250906*g158_0 + 0.18373265651693846*g194_0 + 0.079416392023803101*g28_0 + 0.037184899473111252*g206_0 + -0.029808052353975784*g54_0 + 0.13479242613586978*g160_0 + -0.044154829229400581*g5_0 + -0.11152722920937508*g10_0 + -0.13892324260023078*g57_0 + 0.042522254069200287*g143_0 + 0.049609805428619938*g165_0);
    std::memcpy(moment_arm + 264, &a0, 6 * sizeof(double)); std::memset(moment_arm + 270, 0, 5 * sizeof(double)); L[24] = a0[6]; }
  { const v8d a0 = (0.12983802286119614*g_one_0 + -0.14778530860375511*g8_0 + -0.0006542557132033672*g204_0 + 0.23362634053076023*g171_0 + -0.072770467282033097*g39_0 + 0.089895947984867983*g140_0 + 0.16913965572203873*g170_0 + 0.18258697562929727*g128_0 + -0.062973051080857267*g33_0 + -0.4469367445643983*g131_0 + 0.086195423774028945*g207_0) + (-0.34889567189286558*g187_0 + 0.28383222561991561*g153_0 + -0.1339713966140452*g6_0 + -0.18353134604843541*g56_0 + 0.37170356196489251*g55_0 + 0.040812511129635645*g99_0 + 0.03952384044949106*g58_0 + 0.31275290088302826*g132_0 + 0.21331254922756954*g183_0 + 0.10608931221376716*g165_0 + 0.073030234469279504*g194_0);
    std::memcpy(moment_arm + 275, &a0, 6 * sizeof(double)); std::memset(moment_arm + 281, 0, 5 * sizeof(double)); L[25] = a0[6]; }
  { const v8d a0 = (0.13506167761420193*g_one_0 + -0.13864545810256876*g8_0 + 0.0099658224203611114*g182_0 + 0.10763394401841028*g141_0 + 0.068999364328737253*g173_0 + 0.45904783789309472*g55_0 + 0.25461837214824523*g193_0 + -0.21747222163332106*g56_0 + 0.31132998925327998*g183_0 + 0.026061211841311605*g58_0 + 0.081498619438210809*g201_0 + 0.16853371491566879*g99_0 + 0.06544030286828724*g165_0) + (-0.48333076256066415*g187_0 + -0.0046906944979865743*g198_0 + 0.0076289363705211843*g42_0 + 0.087800326814718638*g194_0 + 0.0026319483048330016*g140_0 + -0.065794864885502902*g33_0 + -0.070600516674916014*g40_0 + 0.22233650119456511*g171_0 + -0.039552464248605423*g34_0 + 0.22823866262063883*g29_0 + -0.10654144326915206*g50_0 + -0.084382620283223714*g46_0);
    std::memcpy(moment_arm + 286, &a0, 6 * sizeof(double)); std::memset(moment_arm + 292, 0, 5 * sizeof(double)); L[26] = a0[6]; }
  { const v8d a0 = (0.11384054789188811*g_one_0 + -0.057380747103750948*g42_0 + 0.25005803044492014*g202_0 + 0.0044392873105084905*g141_0 + 0.09238255681892972*g40_0 + -0.14794912144575439*g169_0 + -0.2345868647722831*g201_0 + -0.12216780612884472*g118_0 + 0.0062877302800752139*g173_0 + -0.085126842480204759*g6_0 + -0.22314868049018122*g49_0 + 0.111753109641444*g167_0) + (-0.14571836456073103*g187_0 + 0.2899226962900458*g54_0 + -0.046671129752438797*g8_0 + 0.04989662676861735*g194_0 + -0.17979197615310744*g56_0 + 0.30656934057731938*g183_0 + 0.24710784226224894*g132_0 + -0.37961414804994092*g186_0 + 0.12521753883501996*g182_0 + 0.19585835796207482*g171_0 + 0.33334802873212943*g55_0);
    std::memcpy(moment_arm + 297, &a0, 6 * sizeof(double)); std::memset(moment_arm + 303, 0, 5 * sizeof(double)); L[27] = a0[6]; }
  { const v8d a0 = (0.11092863337135657*g_one_0 + -0.13513726455164449*g40_0 + 0.074706332593916291*g167_0 + -0.25656148894898195*g56_0 + -0.012857399198728657*g178_0 + 0.48766946116485166*g55_0 + 0.14416982874934639*g171_0 + -0.088545936620202687*g94_0 + 0.12392208423040695*g141_0 + 0.2140109706924431*g58_0 + -0.084340402565127329*g206_0 + -0.081919346195660478*g33_0) + (-0.47545834301265716*g187_0 + -0.015652398728416863*g54_0 + -0.082880765701467504*g8_0 + -0.0042554222962221085*g137_0 + 0.12366757684475529*g84_0 + 0.27297405307762596*g208_0 + -0.047933838593811708*g34_0 + -0.15260546361609723*g49_0 + 0.14393061259594481*g150_0 + 0.075636988414799905*g154_0 + 0.24675352704663681*g183_0);
    std::memcpy(moment_arm + 308, &a0, 6 * sizeof(double)); std::memset(moment_arm + 314, 0, 5 * sizeof(double)); L[28] = a0[6]; }
  { const v8d a0 = (0.087436941142423133*g_one_0 + -0.37953226578961369*g49_0 + -0.13518173079154475*g169_0 + -0.065136132674215808*g165_0 + 0.038194783221144925*g136_0 + -0.11369480978846516*g209_0 + 0.1365236690076469*g172_0 + -0.15533567722673255*g195_0 + 0.11259340958226294*g193_0 + 0.42169249628701116*g194_0 + 0.18241444945181118*g207_0 + 0.088636721987794528*g46_0 + 0.034960846991584305*g59_0) + (-0.3041108174173191*g56_0 + 0.22098662526562243*g182_0 + 0.26149682535187063*g166_0 + -0.025137704765011409*g9_0 + -0.061747086460629826*g5_0 + -0.27136458415845577*g206_0 + 0.14901413916585957*g55_0 + 0.26518069045907999*g153_0 + 0.14560600505853133*g205_0 + 0.097383866511325898*g41_0 + -0.10315144675889573*g204_0 + -0.071694048762141901*g42_0);
    std::memcpy(moment_arm + 319, &a0, 6 * sizeof(double)); std::memset(moment_arm + 325, 0, 5 * sizeof(double)); L[29] = a0[6]; }
  { const v8d a0 = (0.065998415548202197*g_one_0 + -0.052484100935957248*g118_0 + -0.10579652604769524*g201_0 + -0.045760398695851016*g170_0 + -0.1540260997373665*g159_0 + 0.28055014232964876*g207_0 + -0.066386260136797298*g209_0 + 0.036382677296285929*g6_0 + 0.036084830446028837*g8_0 + 0.064537203410185109*g137_0 + 0.077553168361868638*g50_0) + (-0.31479578236662348*g56_0 + -0.065999181129179338*g9_0 + -0.11010590603483542*g205_0 + -0.080705388089216262*g187_0 + -0.25527442167566294*g206_0 + 0.065173377208973399*g202_0 + 0.057799349380002397*g84_0 + 0.078571457690678817*g28_0 + 0.36393154607670719*g194_0 + -0.15249783626081467*g49_0);
    std::memcpy(moment_arm + 330, &a0, 6 * sizeof(double)); std::memset(moment_arm + 336, 0, 5 * sizeof(double)); L[30] = a0[6]; }
  { const v8d a0 = (0.027447419995385643*g_one_0 + 0.019405554938365221*g113_0 + 0.26712788010673483*g188_0 + 0.18006426570981096*g165_0 + -0.20681665650772216*g170_0 + 0.066217137598179307*g41_0 + -0.0017088556675986567*g39_0 + 0.016036248312306527*g6_0 + -0.016356087063557512*g209_0 + -0.010778293967065025*g99_0) + (-0.33886542263337466*g56_0 + 0.075105657627168976*g120_0 + -0.13257043053599399*g167_0 + 0.05022854288603424*g143_0 + 0.0096432992139073304*g171_0 + 0.1817589908684572*g154_0 + -0.029625088166705473*g9_0 + -0.070803459891298839*g137_0 + -0.010045966415870394*g5_0);
    std::memcpy(moment_arm + 341, &a0, 6 * sizeof(double)); std::memset(moment_arm + 347, 0, 5 * sizeof(double)); L[31] = a0[6]; }
  { const v8d a0 = (0.015136916110664183*g_one_0 + 0.11098525015991692*g154_0 + -0.051603973078968572*g140_0 + 0.043134220215958689*g205_0 + -0.14185579725586889*g166_0 + 0.20744505357166612*g188_0 + 0.11693073536183878*g201_0 + 0.058279961138494832*g169_0 + 0.025394054374530628*g137_0) + (-0.29109906182929407*g56_0 + 0.055078296613511372*g120_0 + 0.10499152699806268*g207_0 + 0.089028821481291917*g50_0 + -0.0056893938477586533*g109_0 + -0.043886338073533739*g99_0 + -0.092549060546317591*g131_0 + -0.072091356927429767*g47_0);
    std::memcpy(moment_arm + 352, &a0, 6 * sizeof(double)); std::memset(moment_arm + 358, 0, 5 * sizeof(double)); L[32] = a0[6]; }
  { const v8d a0 = (0.011783749280884543*g_one_0 + -0.17219239042279777*g187_0 + 0.11180125069542587*g201_0 + 0.019851886545506677*g48_0 + -0.19204808725934497*g47_0 + 0.075071243392508966*g29_0 + 0.035143218014942752*g120_0 + 0.039337439088101014*g28_0 + -0.042868922842729397*g195_0 + -0.21481039666168492*g131_0 + 0.055904646929615526*g5_0 + -0.13248481974879475*g169_0 + 0.17423662061084219*g193_0) + (0.30906504097924414*g200_0 + -0.028035273089583083*g182_0 + -0.0027688500810070758*g207_0 + 0.30486251338830789*g164_0 + -0.17345617010036887*g56_0 + -0.12070849859332058*g202_0 + -0.17073368031666208*g58_0 + -0.060351178497995296*g132_0 + -0.0014255871227286698*g154_0 + -0.027957713750214639*g8_0 + -0.16343329829453934*g39_0 + -0.033473500288783563*g209_0 + -0.12657780488605305*g199_0);
    std::memcpy(moment_arm + 363, &a0, 6 * sizeof(double)); std::memset(moment_arm + 369, 0, 5 * sizeof(double)); L[33] = a0[6]; }
  { const v8d a0 = (0.024122583996129335*g_one_0 + -0.055282129035984867*g187_0 + -0.33411408459008629*g47_0 + 0.033312306860520183*g186_0 + -0.032664764677349044*g99_0 + 0.0036594153187176027*g194_0 + 0.025747442688611066*g120_0 + -0.14964709527770587*g154_0 + 0.11639258816625965*g159_0 + 0.079578839108359334*g49_0 + -0.10165831253579603*g41_0 + 0.045340407126415634*g169_0 + 0.10672167480739049*g137_0 + 0.072905827808033855*g183_0) + (-0.0335879661098109*g200_0 + 0.043187604397168157*g5_0 + 0.069485986290485136*g201_0 + -0.021009454484747447*g173_0 + -0.08179402129372057*g56_0 + 0.11012706582514466*g165_0 + 0.045052632509791128*g207_0 + 0.067101462626324535*g29_0 + 0.087590418582463678*g50_0 + 0.051521651249524465*g59_0 + -0.17014163572457749*g166_0 + -0.022048211739255155*g140_0 + -0.10529930627947365*g208_0 + -0.060766959851419465*g57_0);
    std::memcpy(moment_arm + 374, &a0, 6 * sizeof(double)); std::memset(moment_arm + 380, 0, 5 * sizeof(double)); L[34] = a0[6]; }
  { const v8d a0 = (0.10017554218231567*g_one_0 + 0.16061872297749849*g150_0 + -0.055777240504216181*g173_0 + -0.030366432728676951*g178_0 + -0.28654976518562691*g153_0 + -0.10947845257194067*g188_0 + -0.10232072158902668*g99_0 + -0.10076125324265106*g166_0 + 0.11184531205180784*g207_0 + 0.14194357784849693*g50_0 + 0.158534659446572*g170_0 + 0.047435331715194588*g114_0 + 0.077293149646842793*g200_0) + (-0.12709314744225714*g199_0 + -0.18677334785670671*g7_0 + -0.13805249592218588*g205_0 + 0.0047951974289599198*g143_0 + -0.10123338422979865*g58_0 + -0.28520703101528461*g47_0 + -0.15523579179002847*g33_0 + 0.12678765866292929*g118_0 + -0.011159988255835886*g8_0 + 0.10018656891726736*g5_0 + 0.18660847189736304*g183_0 + 0.13614950766131576*g35_0 + -0.11116482706723632*g208_0);
    std::memcpy(moment_arm + 385, &a0, 6 * sizeof(double)); std::memset(moment_arm + 391, 0, 5 * sizeof(double)); L[35] = a0[6]; }
  { const v8d a1 = (0.17458338744227*g_one_1 + -0.10770318217503758*g258_1 + 0.30986650239129165*g17_1 + 0.074989927604106207*g274_1 + -0.0016886970607243729*g16_1 + 0.017291986853230915*g4_1 + 0.0025173069488126404*g283_1 + 0.053284751439595948*g227_1 + 0.05882344749412808*g294_1 + -0.69536966099462127*g69_1 + -0.012366187158333418*g280_1 + -0.010532823152192838*g20_1 + -0.10875886120539222*g253_1) + (-0.013612631431100036*g19_1 + -0.018308499526657113*g3_1 + 0.04072768405181932*g229_1 + -0.0012061220994630767*g248_1 + -0.0051802638780183438*g225_1 + 0.0057634870971738587*g2_1 + -0.0046275337500204334*g18_1 + 0.035020294885006784*g224_1 + 0.0018192178169480953*g74_1 + -0.37583306142076545*g244_1 + 0.049126848994484447*g285_1 + 0.73144530186182344*g220_1);
    std::memset(moment_arm + 396, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 402, &a1, 5 * sizeof(double)); L[36] = a1[5]; }
  { const v8d a1 = (0.1507025905841724*g_one_1 + 0.017123444962302441*g3_1 + 0.024699196771042903*g19_1 + -0.0014441368223903799*g280_1 + 9.943370209169062e-05*g16_1 + 0.024314437533536147*g289_1 + 0.0020405820205962656*g74_1 + -0.019617503404749378*g257_1 + 0.0027117427208195304*g4_1 + 0.0046206182840753977*g276_1) + (0.0057205130014667763*g274_1 + -0.011187372705750149*g244_1 + -0.011632073697313179*g229_1 + 0.015079306660234132*g293_1 + -0.0018945606045842405*g223_1 + -0.01849302371337035*g292_1 + 0.0044540427148652435*g2_1 + -0.0088701476198979924*g285_1 + -0.0054218046619229571*g221_1);
    std::memset(moment_arm + 407, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 413, &a1, 5 * sizeof(double)); L[37] = a1[5]; }
  { const v8d a1 = (0.13464925346654874*g_one_1 + -0.0020054881031428416*g220_1 + 0.052467823473408053*g19_1 + 0.0018816845689139427*g244_1 + 0.0051026900294561563*g2_1 + 0.0087565088397142683*g20_1 + 0.010085859376073173*g229_1 + 0.00041397679765752888*g272_1 + -0.0020875355661059119*g259_1 + 0.026502506939745169*g224_1 + 0.0023909811024190762*g292_1 + -0.010434910751185569*g17_1 + 0.0039659561613393192*g279_1 + -0.13930677476441014*g253_1) + (0.0022047055202757907*g4_1 + -0.0005015810998244912*g16_1 + 0.16310232663833374*g227_1 + -0.048627080101869689*g72_1 + -0.0050864860016349971*g18_1 + -0.084275953096105735*g74_1 + -0.0093610824051377581*g248_1 + -0.0060548529893758914*g289_1 + -0.0034108297490772718*g280_1 + -0.00048377126397353842*g274_1 + 0.0076404634183823436*g3_1 + 0.0079768792076504395*g71_1 + 0.041542077859059272*g285_1);
    std::memset(moment_arm + 418, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 424, &a1, 5 * sizeof(double)); L[38] = a1[5]; }
  { const v8d a1 = (0.11124581252591785*g_one_1 + -0.00051527308307896885*g220_1 + 0.025106775004056166*g19_1 + 0.00031228339417472395*g244_1 + -0.0058449136060040744*g17_1 + -0.0056804879211661977*g249_1 + 0.00054621671882290374*g291_1 + 0.0062408479479142236*g256_1) + (0.0070171240503386877*g4_1 + 0.0052186229662015658*g2_1 + -0.0038505051366410827*g227_1 + 0.0024834018478339399*g280_1 + -0.002459003062719995*g73_1 + -0.0035382438981628691*g289_1 + -0.0032401904811057681*g20_1);
    std::memset(moment_arm + 429, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 435, &a1, 5 * sizeof(double)); L[39] = a1[5]; }
  { const v8d a1 = (0.10374707401724827*g_one_1 + -0.044191958957714106*g17_1 + 0.066003868339126456*g72_1 + -0.098782018006916841*g224_1 + 0.044971508591566262*g69_1 + 0.00041414338178159951*g242_1 + 0.00034799083261965758*g259_1 + 0.0016727510593154487*g274_1 + 0.00041406646088255753*g15_1) + (0.0073717870146191413*g4_1 + 0.0041605993451836795*g2_1 + -0.020039469633582798*g220_1 + -0.0012578285174095552*g289_1 + 0.062444164700628212*g249_1 + -0.0011597276096811282*g252_1 + -0.014455686655844764*g280_1 + 0.00099203142265500712*g16_1);
    std::memset(moment_arm + 440, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 446, &a1, 5 * sizeof(double)); L[40] = a1[5]; }
  { const v8d a1 = (0.14082408825180984*g_one_1 + 0.0014404466927397182*g220_1 + 0.0039829933991610521*g2_1 + 0.026728972314204895*g19_1 + -0.0051075411774681697*g255_1 + 0.0012465974844791589*g285_1) + (0.0049062979826875429*g4_1 + -0.00093978992846853731*g280_1 + -0.014781498709732012*g17_1 + -0.0067236775303026394*g227_1 + 0.0011065356864413953*g67_1 + 0.0032825483693828547*g291_1);
    std::memset(moment_arm + 451, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 457, &a1, 5 * sizeof(double)); L[41] = a1[5]; }
  { const v8d a1 = (0.15695531915671074*g_one_1 + 0.0020872976903146571*g220_1 + -0.015243673964159358*g280_1 + -0.11961795312335717*g224_1 + -0.0078661032978571532*g244_1 + 0.016892156821084737*g69_1 + -0.0036029412479950951*g229_1 + -0.0012367141625408797*g73_1) + (0.00055010945855426185*g75_1 + 0.0067344935173962155*g4_1 + 0.0026479987189324951*g274_1 + 0.0036691878328777858*g2_1 + 0.069225379274361995*g249_1 + 0.087400973157899048*g72_1 + -0.028606814690646982*g17_1);
    std::memset(moment_arm + 462, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 468, &a1, 5 * sizeof(double)); L[42] = a1[5]; }
  { const v8d a1 = (0.13963500623628891*g_one_1 + 0.024061675911017433*g19_1 + 0.0027766936358522704*g2_1 + -0.0011142014688907509*g256_1 + 0.0010374474981920407*g218_1) + (-0.01154774684301673*g17_1 + -0.013291034964295395*g3_1 + -0.0048626277954243171*g72_1 + 0.0032929541424644979*g4_1 + 0.0023193665322437519*g69_1);
    std::memset(moment_arm + 473, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 479, &a1, 5 * sizeof(double)); L[43] = a1[5]; }
  { const v8d a1 = (0.147930754727046*g_one_1 + 0.018175497376546518*g19_1 + 0.0030005858475424408*g2_1 + 0.0042718111817150279*g4_1 + 0.0014200920034824879*g16_1) + (-0.016362903423986486*g3_1 + -0.0035209965428583201*g72_1 + -0.0094995642127121051*g17_1 + 0.0021050460394366551*g69_1 + -0.00036243477661132665*g289_1);
    std::memset(moment_arm + 484, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 490, &a1, 5 * sizeof(double)); L[44] = a1[5]; }
  { const v8d a1 = (0.13801626299561048*g_one_1 + 0.01389745564088918*g19_1 + -0.00308010383123464*g72_1 + -0.002226908965338096*g17_1 + -0.0012230633474402887*g230_1) + (-0.025679811862852866*g3_1 + 0.0036339746253399884*g2_1 + 0.0047412232764931445*g20_1 + 0.0013549811128554107*g67_1);
    std::memset(moment_arm + 495, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 501, &a1, 5 * sizeof(double)); L[45] = a1[5]; }
  { const v8d a1 = (0.12950895209458557*g_one_1 + 0.0027817342352359736*g229_1 + -0.0020914149701694571*g292_1 + 0.0022152292618536473*g67_1) + (-0.029058898351798465*g3_1 + 0.0031957225086752285*g2_1 + -0.00092995637556268231*g69_1 + 0.0048695801142583216*g74_1);
    std::memset(moment_arm + 506, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 512, &a1, 5 * sizeof(double)); L[46] = a1[5]; }
  { const v8d a0 = (0.13937944411691178*g_one_0 + 0.025105202319867008*g102_0 + -0.054250611976089762*g17_0 + -0.047544584128926523*g99_0 + -0.019398182065978528*g93_0 + 0.0063364151996237955*g69_0 + 0.091326459696876083*g84_0 + 0.020588644513523185*g116_0 + -0.0054514635838427321*g120_0 + 0.0021891265780643429*g101_0 + -0.0041893390018733993*g18_0 + -0.10822894099244432*g31_0 + 0.0012024245016873218*g70_0 + 0.0017054550871081105*g73_0 + 0.0082945600643434311*g72_0 + -0.0070744626621049161*g86_0 + -0.013836257099931259*g106_0 + -0.099168967593350185*g29_0 + -0.014439972033851299*g80_0 + 0.0053458092867193175*g105_0) + (0.11014530008765835*g24_0 + -0.0048030648697265314*g27_0 + -0.0103539226725653*g74_0 + 0.028740967921374316*g96_0 + -0.012009131817053155*g4_0 + -0.026129565057302188*g82_0 + 0.095862074807236575*g3_0 + -0.013388426707772103*g108_0 + -0.0026242263082477718*g88_0 + 0.02578318796201674*g25_0 + -0.01051830996124577*g91_0 + -0.027402329579323658*g33_0 + 0.0054612643363878485*g7_0 + 0.010879844192999859*g89_0 + 0.00044217462580346069*g75_0 + 0.023746165783928706*g95_0 + 0.0020098858833849549*g67_0 + -0.036393147088563282*g34_0 + 0.015747689948761998*g22_0 + -0.010692396171112712*g19_0); const v8d a1 = (0.13937944411691178*g_one_1 + 0.025105202319867008*g102_1 + -0.054250611976089762*g17_1 + -0.047544584128926523*g99_1 + -0.019398182065978528*g93_1 + 0.0063364151996237955*g69_1 + 0.091326459696876083*g84_1 + 0.020588644513523185*g116_1 + -0.0054514635838427321*g120_1 + 0.0021891265780643429*g101_1 + -0.0041893390018733993*g18_1 + -0.10822894099244432*g31_1 + 0.0012024245016873218*g70_1 + 0.0017054550871081105*g73_1 + 0.0082945600643434311*g72_1 + -0.0070744626621049161*g86_1 + -0.013836257099931259*g106_1 + -0.099168967593350185*g29_1 + -0.014439972033851299*g80_1 + 0.0053458092867193175*g105_1) + (0.11014530008765835*g24_1 + -0.0048030648697265314*g27_1 + -0.0103539226725653*g74_1 + 0.028740967921374316*g96_1 + -0.012009131817053155*g4_1 + -0.026129565057302188*g82_1 + 0.095862074807236575*g3_1 + -0.013388426707772103*g108_1 + -0.0026242263082477718*g88_1 + 0.02578318796201674*g25_1 + -0.01051830996124577*g91_1 + -0.027402329579323658*g33_1 + 0.0054612643363878485*g7_1 + 0.010879844192999859*g89_1 + 0.00044217462580346069*g75_1 + 0.023746165783928706*g95_1 + 0.0020098858833849549*g67_1 + -0.036393147088563282*g34_1 + 0.015747689948761998*g22_1 + -0.010692396171112712*g19_1);
    std::memcpy(moment_arm + 517, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 523, &a1, 5 * sizeof(double)); L[47] = a0[6]; }
  { const v8d a0 = (0.16984270094976286*g_one_0 + -0.085105074279649556*g5_0 + -0.23502450939283065*g98_0 + 0.028823860539130164*g92_0 + 0.033052544765166739*g109_0 + 0.013799560758567744*g78_0 + -0.0097477048165998757*g74_0 + -0.0043827716794029685*g108_0 + -0.023810362925206718*g19_0 + -0.0027508892659398542*g96_0 + -0.0055614324464986114*g95_0 + -0.0059117720935135997*g2_0 + 0.0034076032925671757*g100_0 + 0.0027682308928808574*g120_0 + -0.055779476632021881*g31_0 + -0.01395160819319999*g80_0) + (0.0037731148037981042*g112_0 + 0.014422471626641032*g107_0 + -0.0046210234265750428*g4_0 + -0.0071622575798614219*g116_0 + -0.27823535985637315*g28_0 + 0.079530993279952125*g3_0 + -0.034498350088437275*g17_0 + -0.018427917994916398*g82_0 + 0.0093399905360294494*g72_0 + -0.012935256883347884*g87_0 + -0.0082145111180601492*g106_0 + 0.0026306076576088216*g68_0 + 0.012719228291730285*g102_0 + 0.079849418890459017*g99_0 + 0.1170429249101796*g113_0 + 0.0094543538654000506*g89_0); const v8d a1 = (0.16984270094976286*g_one_1 + -0.085105074279649556*g5_1 + -0.23502450939283065*g98_1 + 0.028823860539130164*g92_1 + 0.033052544765166739*g109_1 + 0.013799560758567744*g78_1 + -0.0097477048165998757*g74_1 + -0.0043827716794029685*g108_1 + -0.023810362925206718*g19_1 + -0.0027508892659398542*g96_1 + -0.0055614324464986114*g95_1 + -0.0059117720935135997*g2_1 + 0.0034076032925671757*g100_1 + 0.0027682308928808574*g120_1 + -0.055779476632021881*g31_1 + -0.01395160819319999*g80_1) + (0.0037731148037981042*g112_1 + 0.014422471626641032*g107_1 + -0.0046210234265750428*g4_1 + -0.0071622575798614219*g116_1 + -0.27823535985637315*g28_1 + 0.079530993279952125*g3_1 + -0.034498350088437275*g17_1 + -0.018427917994916398*g82_1 + 0.0093399905360294494*g72_1 + -0.012935256883347884*g87_1 + -0.0082145111180601492*g106_1 + 0.0026306076576088216*g68_1 + 0.012719228291730285*g102_1 + 0.079849418890459017*g99_1 + 0.1170429249101796*g113_1 + 0.0094543538654000506*g89_1);
    std::memcpy(moment_arm + 528, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 534, &a1, 5 * sizeof(double)); L[48] = a0[6]; }
  { const v8d a0 = (0.15576230880248026*g_one_0 + 0.014744503130220151*g119_0 + -0.068068076138575573*g31_0 + -0.0015703206836296655*g116_0 + -0.00087791112860847239*g20_0 + 0.001835929438890625*g108_0 + -0.028146333962972486*g17_0 + -0.059039104250469619*g33_0 + 0.0098058238480431704*g72_0 + 0.033578154726706208*g25_0 + -0.0097574139661586751*g74_0 + -0.014895403773614774*g110_0 + 0.021974812988325224*g95_0 + 0.0044451389064344704*g105_0 + -0.0036636913899296695*g86_0 + 0.047429664132813854*g28_0 + 0.0017389494842589173*g107_0 + -0.029045497879416151*g26_0) + (-0.0037669934437862852*g24_0 + -0.027063850816851205*g19_0 + 0.014981005158921552*g102_0 + -0.021995663973803495*g99_0 + 0.066800789643819053*g3_0 + 0.023723866801528395*g27_0 + 0.002532471319692405*g82_0 + -0.033952461590703864*g92_0 + -0.0030628305626507263*g22_0 + -0.0061377006444628505*g77_0 + -0.017983731909360649*g80_0 + 0.040246035219528041*g114_0 + 0.0026204918966480383*g67_0 + 0.019455432174951316*g97_0 + 0.015305154718070944*g78_0 + -0.0054533063647430064*g118_0 + -0.099459414927203463*g29_0); const v8d a1 = (0.15576230880248026*g_one_1 + 0.014744503130220151*g119_1 + -0.068068076138575573*g31_1 + -0.0015703206836296655*g116_1 + -0.00087791112860847239*g20_1 + 0.001835929438890625*g108_1 + -0.028146333962972486*g17_1 + -0.059039104250469619*g33_1 + 0.0098058238480431704*g72_1 + 0.033578154726706208*g25_1 + -0.0097574139661586751*g74_1 + -0.014895403773614774*g110_1 + 0.021974812988325224*g95_1 + 0.0044451389064344704*g105_1 + -0.0036636913899296695*g86_1 + 0.047429664132813854*g28_1 + 0.0017389494842589173*g107_1 + -0.029045497879416151*g26_1) + (-0.0037669934437862852*g24_1 + -0.027063850816851205*g19_1 + 0.014981005158921552*g102_1 + -0.021995663973803495*g99_1 + 0.066800789643819053*g3_1 + 0.023723866801528395*g27_1 + 0.002532471319692405*g82_1 + -0.033952461590703864*g92_1 + -0.0030628305626507263*g22_1 + -0.0061377006444628505*g77_1 + -0.017983731909360649*g80_1 + 0.040246035219528041*g114_1 + 0.0026204918966480383*g67_1 + 0.019455432174951316*g97_1 + 0.015305154718070944*g78_1 + -0.0054533063647430064*g118_1 + -0.099459414927203463*g29_1);
    std::memcpy(moment_arm + 539, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 545, &a1, 5 * sizeof(double)); L[49] = a0[6]; }
  { const v8d a0 = (0.16866224359982682*g_one_0 + 0.044581384853228261*g24_0 + 0.015839346431533664*g99_0 + 0.079991256000661121*g3_0 + -0.019987874835521686*g82_0 + 0.00092723581660268109*g116_0 + -0.021771760767818924*g19_0 + -0.03122885276844729*g17_0 + 0.0030170007903981776*g25_0 + -0.07839768902059599*g28_0 + 0.0099070214824678489*g72_0 + 0.0087085283333061432*g21_0 + 0.0015983935250545049*g86_0 + -0.069237429478493373*g31_0 + -0.0058071071613559778*g2_0 + -0.043212131564607646*g5_0 + -0.01279229349691495*g80_0 + 0.0022025922091344781*g67_0 + -0.0061878471458297456*g104_0) + (-0.0015504091515480508*g112_0 + 0.012594441977209629*g102_0 + -0.0067503950523180355*g4_0 + -0.010701837169857408*g74_0 + -0.003438837616822839*g108_0 + 0.020751249264172468*g84_0 + 0.10370222028847909*g113_0 + 0.0011310610360599159*g120_0 + -0.013287052110585297*g87_0 + -0.012228554730125317*g34_0 + -0.02044273755652282*g106_0 + 0.01506211952526502*g78_0 + -0.00066310730559289747*g76_0 + 0.03551366539863373*g6_0 + 0.0012593029011494104*g95_0 + 0.0035656510033097023*g16_0 + 0.0063386854484205309*g105_0 + 0.0057406053103953719*g89_0 + 0.0054131852547109217*g90_0); const v8d a1 = (0.16866224359982682*g_one_1 + 0.044581384853228261*g24_1 + 0.015839346431533664*g99_1 + 0.079991256000661121*g3_1 + -0.019987874835521686*g82_1 + 0.00092723581660268109*g116_1 + -0.021771760767818924*g19_1 + -0.03122885276844729*g17_1 + 0.0030170007903981776*g25_1 + -0.07839768902059599*g28_1 + 0.0099070214824678489*g72_1 + 0.0087085283333061432*g21_1 + 0.0015983935250545049*g86_1 + -0.069237429478493373*g31_1 + -0.0058071071613559778*g2_1 + -0.043212131564607646*g5_1 + -0.01279229349691495*g80_1 + 0.0022025922091344781*g67_1 + -0.0061878471458297456*g104_1) + (-0.0015504091515480508*g112_1 + 0.012594441977209629*g102_1 + -0.0067503950523180355*g4_1 + -0.010701837169857408*g74_1 + -0.003438837616822839*g108_1 + 0.020751249264172468*g84_1 + 0.10370222028847909*g113_1 + 0.0011310610360599159*g120_1 + -0.013287052110585297*g87_1 + -0.012228554730125317*g34_1 + -0.02044273755652282*g106_1 + 0.01506211952526502*g78_1 + -0.00066310730559289747*g76_1 + 0.03551366539863373*g6_1 + 0.0012593029011494104*g95_1 + 0.0035656510033097023*g16_1 + 0.0063386854484205309*g105_1 + 0.0057406053103953719*g89_1 + 0.0054131852547109217*g90_1);
    std::memcpy(moment_arm + 550, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 556, &a1, 5 * sizeof(double)); L[50] = a0[6]; }
  { const v8d a1 = (0.16294656285998291*g_one_1 + 0.00014132619876644414*g69_1 + 0.009359315095763019*g3_1 + 0.00056570108277336926*g295_1 + -0.0039530878386866853*g74_1 + -0.0075431130070622628*g17_1) + (-0.027644309007924098*g19_1 + 0.00019080463346228063*g280_1 + 0.00088862365924676509*g15_1 + 0.0015811098258672188*g18_1 + 0.0025588638394600537*g229_1 + 0.0027084916010776364*g224_1);
    std::memset(moment_arm + 561, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 567, &a1, 5 * sizeof(double)); L[51] = a1[5]; }
  { const v8d a1 = (0.17678035118133967*g_one_1 + 0.015178222310755735*g3_1 + 0.0069079293574846219*g72_1 + -0.006877463861653511*g74_1 + 0.0009173632489187898*g285_1) + (-0.032082413016259997*g19_1 + -0.0067651353687499674*g17_1 + 0.0014028579967566691*g16_1 + 0.0026646254233158692*g75_1);
    std::memset(moment_arm + 572, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 578, &a1, 5 * sizeof(double)); L[52] = a1[5]; }
  { const v8d a1 = (0.19274097791990649*g_one_1 + -0.0029467456490952031*g69_1 + 0.0047546165046363541*g3_1 + 0.0010660108245561044*g295_1) + (-0.030573050194509552*g19_1 + 0.0012494223749352498*g280_1 + 0.0016105360106883192*g2_1 + -0.0014696298947196847*g74_1);
    std::memset(moment_arm + 583, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 589, &a1, 5 * sizeof(double)); L[53] = a1[5]; }
  { const v8d a1 = (0.088006774260031645*g_one_1 + 0.014995040292306741*g4_1 + 0.003583067746040198*g253_1 + -0.0036576074372212226*g223_1 + -0.0075622000013847029*g15_1 + -0.0023207209129911016*g247_1 + 0.0031034225420507509*g222_1 + -0.0064692470080749739*g20_1 + 0.0014835390595098091*g221_1 + -0.0085022480517435422*g291_1 + 0.0022595998858465217*g228_1 + -0.003025990694297629*g286_1 + 0.011285745880956386*g69_1 + 0.0017755529643894252*g66_1 + -0.0034249340084599152*g292_1) + (-0.015369868892254427*g17_1 + 0.015019029921289055*g2_1 + -0.0045985236932905241*g19_1 + 0.0030054399445767375*g284_1 + -0.0076804853154607781*g220_1 + -0.015330201940712209*g18_1 + 0.0053028572982128626*g73_1 + 0.0002019500476972427*g74_1 + -0.0010149312816355397*g219_1 + 0.0093778444864181659*g255_1 + 0.0067953495375292147*g70_1 + 0.00086080377414804433*g242_1 + 0.0020959195430774158*g244_1 + 8.2050384772797691e-05*g295_1 + 0.0077384799258578899*g229_1);
    std::memset(moment_arm + 594, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 600, &a1, 5 * sizeof(double)); L[54] = a1[5]; }
  { const v8d a1 = (0.17356621612999892*g_one_1 + 0.0069679171336001168*g74_1 + 0.00024494054812902678*g69_1 + -0.0060161974996631746*g19_1 + -0.0055558098165239735*g18_1 + -0.00015339387219721797*g225_1 + 0.00049330848389187473*g220_1 + 0.0040093765235933035*g226_1 + 0.0012273666634509152*g66_1 + 0.0029747427038394349*g70_1 + -0.0034551823471286802*g292_1 + 0.0040975032207306904*g256_1) + (-0.0089510384405577393*g17_1 + 0.011095552258008522*g2_1 + 0.010534497562897094*g4_1 + 0.00073486892350355657*g285_1 + -0.0037437352867697518*g15_1 + 0.0010315201930348888*g75_1 + -0.00059606750620098351*g68_1 + -0.0049801106251140198*g3_1 + -0.0020491538512592291*g223_1 + 0.00054129728991675981*g278_1 + -0.0036889695994661463*g20_1);
    std::memset(moment_arm + 605, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 611, &a1, 5 * sizeof(double)); L[55] = a1[5]; }
  { const v8d a1 = (0.14838254604080264*g_one_1 + 0.010949119986949701*g74_1 + -0.010288938489065579*g17_1 + -0.0077535390780109782*g19_1 + -0.0097260418265631473*g18_1 + 0.0045063713564514598*g251_1 + 0.0055265558271342559*g73_1 + -0.0039599355335162723*g15_1 + 0.0018892639919294116*g69_1 + -0.0069315710061313802*g20_1 + 0.0082001858345322146*g70_1 + 0.0010581670720069755*g217_1) + (-0.0053066784121569279*g3_1 + 0.012015745383368479*g2_1 + 0.012032792953201712*g4_1 + 0.00092905729632579903*g285_1 + 0.0001029954243784302*g218_1 + -0.00010331132460065307*g72_1 + 0.0027665820486616061*g75_1 + -0.0010270174925429774*g68_1 + 0.00024142907899367958*g221_1 + -0.0015037010045402587*g294_1 + -0.0059377847249093884*g225_1 + -0.0033777944487118124*g222_1);
    std::memset(moment_arm + 616, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 622, &a1, 5 * sizeof(double)); L[56] = a1[5]; }
  { const v8d a1 = (0.13969894670294553*g_one_1 + -0.0033328185203357289*g74_1 + 0.0083310179493037463*g4_1 + -0.0048825520256885252*g223_1 + -0.0097319299165037274*g17_1 + -0.0025924897723106927*g15_1 + -0.0048674981527577757*g18_1 + -0.00038053103640238326*g243_1 + 0.0070724221680186451*g227_1 + 0.0048569147141359018*g229_1 + 0.0050766335048692381*g256_1) + (-0.012126377088967079*g3_1 + 0.0108282881940239*g2_1 + -0.0042127053597981337*g72_1 + 0.0025406902926811002*g284_1 + 0.00069794863960227554*g285_1 + 0.0012445813006890503*g222_1 + 0.0029577424371109089*g69_1 + 0.0034636992856434592*g226_1 + -0.0060178425487586876*g292_1 + 0.0024613389116445476*g70_1);
    std::memset(moment_arm + 627, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 633, &a1, 5 * sizeof(double)); L[57] = a1[5]; }
  { const v8d a1 = (0.12636717937802441*g_one_1 + -0.021602665574836467*g3_1 + 0.0012853120881688533*g227_1 + -0.010795375731992891*g72_1 + 0.0011291127928780217*g280_1 + -0.0028410225837076598*g16_1 + -0.012380790225551897*g223_1 + -0.00095999834082819921*g283_1 + -0.0037340850458926753*g295_1 + 0.004955633528151232*g222_1 + 0.01093041192111445*g71_1 + 0.0053334398955706096*g19_1 + -0.0040107628226371036*g291_1) + (0.00013587351389300219*g20_1 + 0.011304899584155181*g2_1 + 0.0085685334054338841*g4_1 + -0.04678242370911484*g292_1 + -0.016331642733785106*g229_1 + 0.0067406727706210917*g284_1 + 0.055243304979457619*g256_1 + -0.0019305875800935681*g15_1 + 0.0017214329646483601*g259_1 + -0.01097566010617345*g18_1 + 0.020267452676843562*g294_1 + 0.0070623504182047688*g73_1);
    std::memset(moment_arm + 638, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 644, &a1, 5 * sizeof(double)); L[58] = a1[5]; }
  { const v8d a1 = (0.10722206496933603*g_one_1 + 0.013567479080866125*g256_1 + 0.022009244398142395*g69_1 + -0.020602625729332101*g71_1 + -0.0044872666666599852*g3_1 + -0.0065163491349425305*g20_1 + -0.002725205192022506*g15_1 + 0.036736693943344785*g288_1 + 0.00066656318667792486*g218_1 + -0.006686510366697926*g294_1 + -0.029076216738602521*g255_1) + (-0.028497220751622955*g17_1 + 0.01167299019496483*g2_1 + 0.011700640347370931*g4_1 + 0.031899702567619315*g226_1 + -0.0037955457104507356*g72_1 + -0.0057692739656735039*g220_1 + 0.003267748391580986*g222_1 + 0.0026801303684561603*g279_1 + -0.023459462904635651*g284_1 + 0.0054226905281691976*g230_1 + -0.002598391211886581*g18_1);
    std::memset(moment_arm + 649, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 655, &a1, 5 * sizeof(double)); L[59] = a1[5]; }
  { const v8d a1 = (0.09315877706334319*g_one_1 + 3.5301682717440235e-06*g274_1 + 0.014045317956737226*g2_1 + -0.0019869033534603182*g19_1 + 0.017308766582397841*g3_1 + 8.7899297896903021e-05*g242_1 + -0.0057011711653609564*g20_1 + 0.00065297039062390204*g67_1 + -0.00039866840403668348*g279_1 + 0.0050789903196014809*g66_1 + 0.012951499842115521*g70_1 + 0.0016908677948509567*g252_1 + 0.002266794079587501*g227_1 + 0.0037816573019422962*g281_1 + -0.00091498997929429881*g291_1 + -0.00062460016921501624*g294_1) + (-0.011955670537629567*g18_1 + 0.013839796477325668*g4_1 + -0.0011120359171408259*g72_1 + -0.00029938818582666551*g249_1 + -0.0093555757120032876*g17_1 + 0.00069006645348913289*g285_1 + 0.0067495492404286931*g73_1 + 0.00015548144988738062*g222_1 + -0.0079145490701789875*g15_1 + -0.0010194872932794154*g68_1 + -0.0067051052843509901*g225_1 + -0.00096754092612443172*g276_1 + -0.0055557207906123751*g221_1 + -0.0015294651188885895*g216_1 + 0.0012068835300714413*g230_1);
    std::memset(moment_arm + 660, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 666, &a1, 5 * sizeof(double)); L[60] = a1[5]; }
  { const v8d a1 = (0.10960419230259845*g_one_1 + 0.00065066127836002218*g220_1 + 0.014835303185936129*g2_1 + 0.00011372818869865523*g218_1 + -0.0001302627916489056*g274_1 + -0.011014370345540292*g17_1 + -0.0070707035476625978*g15_1 + 0.0004843747944508368*g284_1 + -0.0039755746328562457*g249_1 + 0.0027236697676880288*g216_1 + 0.004457223627491012*g226_1 + 0.00090901220449426078*g278_1 + 0.0017153848180389922*g280_1 + 0.0029464615106719822*g73_1 + -0.0025603315458946241*g292_1) + (-0.011067333136799791*g18_1 + 0.012521930587662832*g4_1 + -0.0027198171992369991*g289_1 + -0.0030448378539296331*g287_1 + 0.013510427769020729*g3_1 + -0.0060363963223625033*g74_1 + -0.0030250053729758801*g223_1 + -7.1941210837239467e-05*g251_1 + 0.003432569947129197*g253_1 + 0.0080900894464779639*g70_1 + 0.0089548306495720164*g256_1 + -0.0021990842566022221*g20_1 + -0.0024513247770276314*g275_1 + -0.00035075300406264923*g219_1);
    std::memset(moment_arm + 671, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 677, &a1, 5 * sizeof(double)); L[61] = a1[5]; }
  { const v8d a1 = (0.069572182077032738*g_one_1 + 0.0020338858158611057*g220_1 + 0.014806649057972587*g2_1 + 0.00044942756124782758*g242_1 + -0.0051583545297041837*g20_1 + -0.0019378285623766957*g19_1 + 0.0079705365070204207*g3_1 + -0.0068643222112683639*g69_1 + 0.00083688731463800589*g284_1 + 0.0036982577336502199*g226_1 + 0.0010757785312054374*g270_1 + 0.003718277067390135*g258_1) + (-0.01068819018639932*g18_1 + 0.014916963429265235*g4_1 + 0.004554817613066176*g289_1 + -0.0014210331578339225*g287_1 + -0.00050764140234508474*g224_1 + -0.00046080370514730456*g249_1 + -0.005292442056554672*g15_1 + -0.0028655218423130698*g223_1 + 0.0059269623562030957*g70_1 + -0.0010142322045045898*g68_1 + -0.005288343057224104*g292_1 + 0.0029639052612313518*g73_1);
    std::memset(moment_arm + 682, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 688, &a1, 5 * sizeof(double)); L[62] = a1[5]; }
  { const v8d a1 = (0.092361352698177038*g_one_1 + -0.008981844348677305*g20_1 + -0.010525880556632878*g2_1 + 0.0036541275866262663*g70_1 + -0.014713213780803725*g69_1 + -0.0074015361807005693*g227_1 + 0.0023611656373560505*g15_1 + 0.0044262685502845824*g289_1 + 0.00096869293613083729*g295_1 + 0.0011658761718553203*g73_1) + (0.059854005539370161*g3_1 + 0.0014139893629133973*g244_1 + 0.0029135707294001317*g18_1 + -0.0041293449600124515*g292_1 + 0.0076841181517891856*g249_1 + 0.0019730294367657606*g68_1 + -0.0040729426872828135*g280_1 + 0.014006391792384807*g17_1 + -0.0010840324416225594*g278_1);
    std::memset(moment_arm + 693, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 699, &a1, 5 * sizeof(double)); L[63] = a1[5]; }
  { const v8d a1 = (0.10840427738385608*g_one_1 + -0.009934705688330981*g20_1 + -0.0095286852666296874*g2_1 + -0.00054721462284513665*g229_1 + 0.0030849671661495291*g16_1 + -0.0078581456084737249*g74_1) + (0.082916301829129457*g3_1 + -0.0069791722854249238*g69_1 + 0.0026459248234464625*g4_1 + 0.0048640672931719942*g70_1 + 0.0021149482353788954*g224_1);
    std::memset(moment_arm + 704, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 710, &a1, 5 * sizeof(double)); L[64] = a1[5]; }
  { const v8d a1 = (0.10317986006414963*g_one_1 + -0.00635085207611752*g69_1 + -0.0073686469774345044*g2_1 + -0.0069888186050911256*g20_1 + -0.00029764105417489148*g229_1 + 0.0010994536177557476*g219_1 + -0.01153026514211068*g74_1) + (0.070570867527538009*g3_1 + 0.00058621607052375629*g75_1 + -0.001486850941130935*g4_1 + -0.00021307855925561863*g246_1 + 0.012252641520860814*g19_1 + 0.0049589816153312203*g70_1);
    std::memset(moment_arm + 715, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 721, &a1, 5 * sizeof(double)); L[65] = a1[5]; }
  { const v8d a1 = (0.089122058405541812*g_one_1 + -0.012145840975619675*g20_1 + -0.0079328841005514641*g69_1 + -0.0012410649188842355*g243_1 + -0.0027392883334447435*g249_1 + 0.0084701862753587404*g17_1 + 0.0010910202297975732*g280_1 + 0.0057655896475918237*g73_1 + -0.002544506913053619*g283_1 + -0.0066788413052626299*g4_1 + -0.016757954687237939*g229_1) + (0.043108470829151889*g3_1 + -0.011728770824699456*g2_1 + 0.0061809430448025145*g70_1 + 0.0060986104470848118*g256_1 + -0.0018134171610291682*g228_1 + 0.010262465769351329*g75_1 + 0.0019365094570209945*g66_1 + 0.003323725618563405*g219_1 + 0.0010311079006121813*g220_1 + 0.010983527426828279*g19_1);
    std::memset(moment_arm + 726, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 732, &a1, 5 * sizeof(double)); L[66] = a1[5]; }
  { const v8d a1 = (0.090826472479207152*g_one_1 + -0.00078050872463237338*g73_1 + 0.0079685164663693825*g67_1 + 0.00036550948408811332*g289_1 + -0.0055723869186777132*g16_1 + 0.00041907969814635403*g279_1 + -0.010579408556972751*g15_1 + -0.0002917619156133129*g230_1 + 0.005682791497830313*g71_1 + 0.0031585338320213028*g255_1 + 0.0064178150923754947*g284_1 + 0.010837231611755014*g4_1 + -0.020711853134426535*g18_1 + 0.0027101565387618745*g244_1 + -0.0034875523828313934*g220_1 + -0.0085490079160522817*g252_1) + (-0.021301190269724386*g3_1 + -0.0015779369648536816*g70_1 + 0.002591773470724079*g225_1 + -0.0060680055243291248*g248_1 + 0.0035100308825640851*g278_1 + -0.00086303919387192363*g288_1 + -0.0083676936862365405*g19_1 + 0.00036139677117695741*g72_1 + 0.010867390368272611*g2_1 + -0.00048847126855582014*g274_1 + -0.0052117633599239339*g283_1 + -0.010549922805313913*g20_1 + 0.0098370716404888939*g74_1 + 0.0034573170606739109*g68_1 + 0.0021849809461160319*g286_1);
    std::memset(moment_arm + 737, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 743, &a1, 5 * sizeof(double)); L[67] = a1[5]; }
  { const v8d a1 = (0.094982056840290638*g_one_1 + -0.0021048645161224769*g73_1 + -0.0027411776082847368*g71_1 + -0.010217079828536531*g15_1 + 0.002505726011993047*g225_1 + -0.0068787491607574438*g20_1 + 0.00034958367254630553*g272_1 + 0.012210937450381161*g2_1 + -0.017187582981527134*g18_1 + -0.0051980788487949008*g251_1 + -0.00079523420482003465*g274_1 + -0.0035257309396143038*g220_1 + 0.0034219013017547676*g244_1) + (-0.021289269834287177*g3_1 + -0.001982720535005564*g16_1 + 0.0056013336027123705*g256_1 + 0.0038697089308848431*g283_1 + 0.0099333560257323979*g4_1 + 0.0013580564139935606*g68_1 + 0.0058440287490802737*g226_1 + -0.0061140460321746255*g72_1 + 0.0037451946818606008*g253_1 + 0.0078988155964678456*g67_1 + -0.0035220837031621614*g289_1 + -0.0050870885277981646*g252_1 + -0.00036980456985236511*g259_1);
    std::memset(moment_arm + 748, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 754, &a1, 5 * sizeof(double)); L[68] = a1[5]; }
  { const v8d a1 = (0.11572828009286683*g_one_1 + 0.0045667288541326474*g227_1 + 0.0055644644372263106*g73_1 + -0.014615326976820029*g18_1 + -0.014698757723615341*g247_1 + 0.0069190952969535903*g278_1 + 0.0047209356879158101*g218_1 + -0.0085225467136463944*g2_1 + 0.0030402481637777598*g254_1 + -0.001323860891908551*g284_1 + 0.012781612638597247*g222_1 + 0.004206131923060334*g221_1 + -0.0036413644058339635*g289_1 + -0.003527423799356505*g282_1) + (-0.0035938471653815126*g19_1 + -0.018650808461072862*g3_1 + 0.00017607231074876441*g273_1 + -0.010622311788169041*g4_1 + -0.0054674683495409583*g15_1 + 0.0049742375142757499*g69_1 + -0.0011098287361955559*g243_1 + 0.0096068474056155533*g68_1 + -0.0011807087436943588*g72_1 + 0.0065511006574232953*g256_1 + -0.0064566908296833517*g17_1 + -0.0026242652956580672*g20_1 + -0.0012698391415856664*g272_1);
    std::memset(moment_arm + 759, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 765, &a1, 5 * sizeof(double)); L[69] = a1[5]; }
  { const v8d a1 = (0.093219747075903442*g_one_1 + 0.011605094266265393*g227_1 + 0.00012390342292509463*g271_1 + -0.001558767247031517*g17_1 + -0.012406017860309981*g4_1 + -0.01163734442033189*g18_1 + 0.0039529822573181345*g16_1 + -0.0016155780394358351*g284_1 + 0.0046832907231106422*g228_1 + -0.017151186205377721*g72_1 + 0.0070634005817428267*g224_1 + 0.011712314541734631*g250_1 + -0.01012596609058963*g282_1 + -0.0054671623934566156*g278_1) + (0.0069644509191084565*g19_1 + -0.01124018795462476*g2_1 + 0.0034813367574372533*g69_1 + 0.0074037786911381048*g68_1 + -0.022625077197783085*g3_1 + -0.00048590142943937166*g254_1 + -0.0023176796856425397*g285_1 + 0.014020722386561062*g247_1 + -0.00028861270756187427*g273_1 + -0.0044335106794248548*g20_1 + 0.0018265121287478381*g75_1 + -0.0025241536927605333*g216_1 + 0.0028417804553213916*g240_1 + -0.0011997134308845249*g15_1);
    std::memset(moment_arm + 770, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 776, &a1, 5 * sizeof(double)); L[70] = a1[5]; }
  { const v8d a1 = (0.075512624363119604*g_one_1 + -0.0011018580777554772*g286_1 + 0.0063756266644584012*g75_1 + 0.0077666245513160238*g66_1 + -0.022454522303246655*g2_1 + 0.00023258224149381751*g68_1 + -6.3999682912662843e-05*g274_1 + 0.0216034651883317*g73_1 + -0.013999604958139743*g3_1 + 0.016915911422590156*g17_1 + 0.0040675124491382679*g273_1 + -0.0010469221122218785*g253_1 + 0.0045229097061252289*g224_1 + -0.019892807669968472*g252_1 + -0.00077519634112797734*g289_1 + 0.0055682663348327194*g284_1 + -0.0057984183054471611*g290_1 + 0.0091498841418506758*g218_1 + 0.023987787822662549*g219_1 + -0.0012728736351211196*g249_1) + (-0.0023604371620093842*g69_1 + -0.025695063623319057*g4_1 + 0.0053512635718339068*g226_1 + 0.026937388589330123*g70_1 + 0.00085540062716320763*g288_1 + -0.014592150685481278*g222_1 + 0.00070095023931651722*g18_1 + -0.010759351817611932*g241_1 + 0.010805502340229681*g71_1 + 0.0049975888040479054*g20_1 + -0.00058028302974155559*g72_1 + 0.0081166633552232949*g282_1 + -0.0014678905514465494*g275_1 + -0.0022155258301897623*g293_1 + 0.0051611743404759523*g271_1 + -0.012555438260336426*g250_1 + -0.012823655401597673*g242_1 + -0.018683902953961388*g243_1 + 0.003901090629486007*g272_1 + 0.0031348488726201129*g287_1);
    std::memset(moment_arm + 781, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 787, &a1, 5 * sizeof(double)); L[71] = a1[5]; }
  { const v8d a1 = (0.095899448903829648*g_one_1 + 0.010312542499648752*g73_1 + 0.00047637998576463119*g259_1 + -0.017782594439989082*g4_1 + -0.002254219612197995*g71_1 + -0.0033002653810483931*g252_1 + -0.00043616533649805606*g277_1 + -0.0016200315989085392*g221_1 + 0.023807021254190465*g68_1 + 0.020096775087246846*g18_1 + -0.01781247794564032*g219_1 + 0.0047080979010611203*g243_1 + 0.0092320705527352085*g70_1 + 0.0035627390484921379*g287_1) + (0.012113190352319747*g17_1 + 0.0015046135701127325*g224_1 + -0.0045661670529193975*g257_1 + 0.014230864608345746*g20_1 + -0.016725417128874112*g2_1 + 0.013895732011913723*g15_1 + 0.0015563329626725232*g226_1 + -0.00026685738476175534*g274_1 + -0.012300298103124298*g67_1 + -0.0021637468069288001*g253_1 + -0.0030874524035429682*g3_1 + -0.0012109992813561744*g281_1 + -0.01076322286979*g225_1);
    std::memset(moment_arm + 792, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 798, &a1, 5 * sizeof(double)); L[72] = a1[5]; }
  { const v8d a1 = (0.11592497560882645*g_one_1 + 0.0022707286674296945*g75_1 + -0.0030925987910464256*g287_1 + 0.00014842552136899625*g216_1 + 0.0045228426430478251*g273_1 + -0.0013620507733614594*g71_1 + -0.018153201845508206*g243_1 + 0.010176090681812234*g73_1 + 0.022508966438444487*g219_1 + 0.0034609014591723839*g20_1 + 0.0028011941873930164*g229_1 + -0.00045425503561258561*g289_1 + -0.0010878118479406334*g19_1) + (-0.023549322449860959*g4_1 + -0.0010640333341646157*g244_1 + 0.0030258277042671468*g66_1 + 0.0015528866123511102*g225_1 + -0.020726622168457338*g2_1 + -0.014578246773800388*g3_1 + 0.0043578917950877457*g17_1 + 0.010143408755966598*g70_1 + -0.0025601024236715703*g241_1 + -0.0023039980194796031*g284_1 + 0.0027561205226812168*g220_1 + 0.004262433634098871*g223_1);
    std::memset(moment_arm + 803, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 809, &a1, 5 * sizeof(double)); L[73] = a1[5]; }
  { const v8d a1 = (0.11844492735459632*g_one_1 + -0.025129606747833023*g2_1 + -0.0082319880330347043*g3_1 + 0.0018518448664789251*g17_1 + 0.0019104997433429397*g221_1 + 0.001223182247972403*g252_1 + 0.010451554070810571*g228_1 + 0.00089634996285656624*g230_1 + -0.0095766966119518373*g73_1 + -0.0015987012328949717*g15_1 + -0.0015415791551807842*g283_1) + (-0.024878029832348394*g4_1 + 0.0084673678190704052*g68_1 + -0.0056344399060740107*g254_1 + -9.292677140359599e-06*g75_1 + -0.0020010432347564401*g67_1 + 0.0018625621679692276*g278_1 + 0.0018569842053449762*g66_1 + 0.015076572361656255*g225_1 + -0.0026396835895730773*g288_1 + 0.0003069244371176765*g294_1);
    std::memset(moment_arm + 814, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 820, &a1, 5 * sizeof(double)); L[74] = a1[5]; }
  { const v8d a1 = (0.11909785774291502*g_one_1 + -0.023051243737646665*g4_1 + 0.0013274451205255325*g279_1 + 0.010307458561895388*g219_1 + 0.00023778368920201153*g295_1 + -0.0055499874373101379*g286_1 + -0.00069722164857561469*g74_1 + 0.00023053770988363395*g245_1 + -0.002972513938988371*g278_1 + 0.0022760769727131949*g257_1 + -0.0018443332053863948*g284_1 + -0.00038317103172964286*g224_1 + 0.0091321891973702093*g250_1 + 0.0071860642303024289*g247_1 + 0.00043981697666137552*g272_1) + (-0.023730508930462125*g2_1 + 0.00041021638119618001*g19_1 + -0.0080709864407908505*g3_1 + 0.0035695363921185515*g254_1 + 5.4181954675696225e-05*g226_1 + -0.00036708945268882118*g15_1 + -0.0038442611189009944*g243_1 + 0.0012438551572325667*g223_1 + -0.0037440187760439201*g67_1 + -0.0079139733267132081*g71_1 + 0.00010034841625137004*g274_1 + 0.0017393315315317424*g229_1 + -0.00085427006294893195*g17_1 + 0.00087874716661838319*g239_1);
    std::memset(moment_arm + 825, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 831, &a1, 5 * sizeof(double)); L[75] = a1[5]; }
  { const v8d a1 = (0.14231247220402973*g_one_1 + -0.024007763364639171*g4_1 + -0.010637418620020879*g225_1 + 0.00018453255604255683*g295_1 + -0.0031909411658428781*g226_1 + 0.0062017059115024907*g247_1 + -0.0034034173498247453*g16_1 + 0.00053826392101568503*g270_1 + -0.0044793078110146201*g283_1 + 0.017598119386501396*g254_1) + (-0.025075324151714484*g2_1 + 0.0077487487525613437*g219_1 + -0.0024758916064649022*g3_1 + -0.021387012076275587*g286_1 + -0.0027670365062369764*g67_1 + -0.0010867660537896057*g273_1 + 0.0037316678211110873*g228_1 + -0.0033756897870230789*g18_1 + 0.025082346232108758*g250_1);
    std::memset(moment_arm + 836, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 842, &a1, 5 * sizeof(double)); L[76] = a1[5]; }
  { const v8d a1 = (0.13680734905770628*g_one_1 + -0.021782333761680605*g4_1 + 0.0078910529718945552*g250_1 + -0.017825499351993186*g16_1 + 0.0035522090220434384*g70_1 + -0.0029615103458038084*g291_1 + -0.0013641584186206404*g74_1 + 0.0019049477925510436*g239_1 + 0.00011292705429051296*g244_1 + -0.0017474203520165728*g67_1 + 0.0049039211535526284*g222_1) + (-0.020731523990023482*g2_1 + -0.00063366904882912695*g243_1 + 0.0014501799750359196*g230_1 + 0.015583783338989955*g68_1 + -0.0057929544746344987*g293_1 + -0.0005525239971313229*g280_1 + 0.011834479510304339*g257_1 + -0.00082686920564537165*g3_1 + 0.0010368102175122933*g249_1 + -0.0022038581174492824*g18_1 + -0.0045670535571089074*g282_1);
    std::memset(moment_arm + 847, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 853, &a1, 5 * sizeof(double)); L[77] = a1[5]; }
  { const v8d a1 = (0.095569274998744916*g_one_1 + -0.021949135020791731*g4_1 + 0.0087898449949352104*g225_1 + -5.466098088532096e-05*g273_1 + 0.00033381622578192849*g295_1 + 0.0001380533006608781*g72_1 + -0.0031041137858471499*g20_1 + 0.0036075327869102801*g228_1 + 0.0099367007375615289*g248_1 + -0.0059140046091147869*g71_1 + -0.0022262669669770034*g3_1 + 0.0012457116015030631*g17_1 + -0.0018029485381495164*g15_1 + 0.0025356888519013302*g75_1) + (-0.022705598096231419*g2_1 + -0.00048729172327229535*g219_1 + -0.012023842938927441*g16_1 + 0.0075890020750033248*g250_1 + -0.0012951179521305865*g229_1 + 0.00097169737700152623*g74_1 + 0.0063442671839460752*g275_1 + -0.0046225272565112744*g252_1 + 0.012281735081611707*g68_1 + -2.9218221645802485e-06*g274_1 + -0.0036986242309063572*g279_1 + -0.0094914891283777534*g281_1 + 0.0013935900926752656*g66_1);
    std::memset(moment_arm + 858, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 864, &a1, 5 * sizeof(double)); L[78] = a1[5]; }
  { const v8d a1 = (0.11357964334201984*g_one_1 + -0.018967514333607671*g4_1 + 0.0023384891056725441*g221_1 + -0.00084085519132682922*g257_1 + -0.0016067660788744711*g291_1 + -0.0018598074445868033*g244_1 + 0.0023359660275356722*g66_1 + 0.0012107164262443841*g230_1 + -0.00083629568104189251*g74_1 + 0.0059759424731129929*g228_1 + -0.00086452751224263061*g227_1 + -0.0014825879523899432*g284_1) + (-0.019602718107215159*g2_1 + 0.0036896834978402829*g69_1 + -0.0010499449076210854*g219_1 + 0.0033676389002822629*g70_1 + -0.015351724999051903*g16_1 + 0.0030148893322382371*g248_1 + -0.00068715554631016101*g279_1 + 0.0052352038384124921*g225_1 + 0.0011536554362879437*g72_1 + 0.012368140905740805*g68_1 + 0.00064332907841056514*g274_1 + -0.0017614355346029203*g287_1);
    std::memset(moment_arm + 869, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 875, &a1, 5 * sizeof(double)); L[79] = a1[5]; }
  { const v8d a1 = (0.057218952396356805*g_one_1 + -0.015492233174176858*g4_1 + 0.0056709602384174412*g222_1 + 0.0039285639643643665*g71_1 + 0.0022204279355116539*g17_1 + 0.0073297831647405167*g19_1 + -0.014295731128645116*g251_1 + 0.0038006303492561342*g228_1 + -0.0014921792112604368*g293_1) + (0.013167293682982539*g3_1 + -0.017705291161546059*g2_1 + -0.0052797252338769298*g74_1 + 0.0024018674966674522*g66_1 + 0.01168054173592852*g225_1 + 0.0019193623866061694*g68_1 + -0.00038703432555743894*g280_1 + 0.00049416093720749781*g295_1 + 0.0023778282223332523*g283_1);
    std::memset(moment_arm + 880, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 886, &a1, 5 * sizeof(double)); L[80] = a1[5]; }
  { const v8d a1 = (0.037199383928831625*g_one_1 + 0.00095929729017872807*g75_1 + 0.0030447392678209623*g254_1 + -0.0067119311340543093*g225_1 + 0.00047075261924116589*g292_1 + 0.0020686071480918869*g216_1 + -0.012610378762051773*g4_1 + 0.0093916135646497402*g70_1 + -0.0029309087490361719*g276_1 + 0.00036970671128350798*g274_1 + -0.011097521450473945*g255_1 + 0.0027005527257158257*g15_1 + 0.0042644329999193976*g288_1) + (0.021236054593630184*g3_1 + -0.014778813758578511*g2_1 + 0.0012985144407455216*g20_1 + 0.0010771378610969313*g257_1 + 0.0051403245198481636*g16_1 + 0.010106064341414325*g73_1 + 0.010359026137261956*g19_1 + -0.0087956157798328508*g74_1 + -0.00076758092969578652*g249_1 + -0.00050893202946535509*g244_1 + 0.0025308674281596557*g71_1 + -0.0014524514444762512*g67_1 + -0.00043016187326383774*g219_1);
    std::memset(moment_arm + 891, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 897, &a1, 5 * sizeof(double)); L[81] = a1[5]; }
  { const v8d a1 = (0.39258177063885152*g_one_1 + -0.022977883215419943*g3_1 + -0.00015325764572231867*g4_1 + 0.0059827578599186172*g218_1 + -0.00086737728666888179*g62_1 + 0.0016323705113327125*g214_1 + -0.0066314051989795966*g20_1 + 0.0017777701136848535*g0_1 + -0.0024106188389399832*g66_1) + (-0.025853828779499349*g1_1 + 0.0022768877739125074*g73_1 + 0.0049096549338458343*g12_1 + -0.014956479029786853*g18_1 + -0.00028299428029588335*g213_1 + -0.016847958713126065*g13_1 + 0.0027577646132295702*g74_1 + -8.6726800796514735e-05*g211_1 + 0.0034466361379576291*g221_1);
    std::memset(moment_arm + 902, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 908, &a1, 5 * sizeof(double)); L[82] = a1[5]; }
  { const v8d a1 = (0.35352503809417579*g_one_1 + -0.039543911481044185*g19_1 + 0.00098851427431825541*g214_1 + -0.0028835086270963596*g227_1 + 0.0063902729850981912*g224_1 + 0.0024967555865351562*g228_1 + 0.0044625599574396706*g229_1 + 0.0024318602900161813*g12_1 + 0.010748889251046974*g3_1 + -0.00058563472061855314*g11_1) + (-0.026058255851233308*g1_1 + 0.0044410487637062731*g0_1 + -0.02178241391038584*g13_1 + -0.00039120061642218919*g69_1 + 0.0010513260601565484*g67_1 + -0.0078749889504705958*g17_1 + -0.00041948935654077124*g213_1 + -0.00027693154455234431*g215_1 + 0.0013758409759407374*g65_1 + 0.003874222283257294*g63_1);
    std::memset(moment_arm + 913, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 919, &a1, 5 * sizeof(double)); L[83] = a1[5]; }
  { const v8d a1 = (0.35352503809417579*g_one_1 + -0.039543911481044185*g19_1 + 0.00098851427431825541*g214_1 + -0.0028835086270963596*g227_1 + 0.0063902729850981912*g224_1 + 0.0024967555865351562*g228_1 + 0.0044625599574396706*g229_1 + 0.0024318602900161813*g12_1 + 0.010748889251046974*g3_1 + -0.00058563472061855314*g11_1) + (-0.026058255851233308*g1_1 + 0.0044410487637062731*g0_1 + -0.02178241391038584*g13_1 + -0.00039120061642218919*g69_1 + 0.0010513260601565484*g67_1 + -0.0078749889504705958*g17_1 + -0.00041948935654077124*g213_1 + -0.00027693154455234431*g215_1 + 0.0013758409759407374*g65_1 + 0.003874222283257294*g63_1);
    std::memset(moment_arm + 924, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 930, &a1, 5 * sizeof(double)); L[84] = a1[5]; }
  { const v8d a1 = (0.28810482745662963*g_one_1 + 0.018858723428750376*g1_1 + 0.002316555133211154*g4_1 + 1.225328770015525e-05*g14_1 + 0.007683884841880438*g227_1 + -0.024041041142686764*g74_1) + (0.040383697740527719*g3_1 + -0.0014963532796749772*g220_1 + 0.0012621978471176545*g20_1 + -0.0090516803515194519*g72_1 + 0.028051818099328107*g19_1 + 0.0031334058079304024*g2_1);
    std::memset(moment_arm + 935, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 941, &a1, 5 * sizeof(double)); L[85] = a1[5]; }
  { const v8d a1 = (0.29851052489341945*g_one_1 + 0.0185762041629761*g1_1 + -0.0010440110117515603*g220_1 + -0.010782598924300143*g74_1 + 0.0014876906372668396*g256_1) + (0.031806554247360549*g3_1 + -0.0010966894421396548*g229_1 + 0.0068056624321065663*g19_1 + 0.0012365784836060455*g14_1);
    std::memset(moment_arm + 946, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 952, &a1, 5 * sizeof(double)); L[86] = a1[5]; }
  { const v8d a1 = (0.32612558627963856*g_one_1 + 0.018556453250211238*g1_1 + 0.0021819030550427727*g4_1 + 0.0012854061204449398*g14_1 + 0.0052053008517023497*g227_1 + -0.016593637306579957*g74_1) + (0.029790786458892146*g3_1 + -0.0010802744316574435*g220_1 + 0.00017675621573766956*g20_1 + -0.0058642149250188076*g72_1 + 0.018673126882267785*g19_1);
    std::memset(moment_arm + 957, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 963, &a1, 5 * sizeof(double)); L[87] = a1[5]; }
  { const v8d a1 = (0.32205960375072529*g_one_1 + 0.018591029345852893*g1_1 + -0.00067389502883742451*g244_1 + -0.0043729517208540777*g20_1 + 0.00032640136928982515*g259_1 + 0.00086641159231339818*g224_1) + (0.032446741954664127*g3_1 + -0.0003626109450318745*g258_1 + 0.0056036734973396894*g4_1 + 0.0011864572809562597*g14_1 + -0.0056746789532388748*g74_1);
    std::memset(moment_arm + 968, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 974, &a1, 5 * sizeof(double)); L[88] = a1[5]; }
  { const v8d a0 = (0.27234228352956336*g_one_0 + 0.0039947049631310003*g47_0 + -0.092278291777668997*g178_0 + 0.0038969736469769401*g105_0 + 0.0040650884405309335*g51_0 + 0.18406628288140481*g56_0 + 0.026369336063687354*g143_0 + 0.04005567341841175*g205_0 + 0.030367471989795128*g23_0 + -0.035933461851340318*g184_0 + -0.29079322910948563*g55_0 + -0.0420162962847263*g180_0 + 0.021963392488271134*g181_0 + -0.021745426570983186*g32_0 + -0.061833146152835819*g28_0 + -0.13341226504240064*g96_0 + 0.0071882926711274919*g103_0 + 0.07602574900471111*g34_0 + 0.012657805485281514*g86_0 + 0.0072364649468001762*g100_0 + -0.072135956663836237*g201_0 + 0.29806953287768162*g29_0) + (0.38537540449817981*g187_0 + 0.037820975741386653*g37_0 + 0.0082265640016904139*g50_0 + -0.019752844154623275*g139_0 + 0.087952446184315039*g9_0 + 0.17181401619741479*g6_0 + -0.15136511005519163*g26_0 + 0.032875028408642148*g111_0 + -0.017894619352488653*g2_0 + -0.011243043887263993*g157_0 + 0.0046303233300942406*g19_0 + 0.043525414354558228*g8_0 + -0.0011805165034969643*g67_0 + -0.011196400450529087*g74_0 + 0.18398321247110488*g99_0 + -0.019201189893902165*g122_0 + 0.21046081675149847*g182_0 + 0.0060045850408073182*g68_0 + 0.01483394469900289*g91_0 + -0.060902233259077454*g166_0 + -0.20079600480014925*g183_0 + 0.032794210682105723*g83_0); const v8d a1 = (0.27234228352956336*g_one_1 + 0.0039947049631310003*g47_1 + -0.092278291777668997*g178_1 + 0.0038969736469769401*g105_1 + 0.0040650884405309335*g51_1 + 0.18406628288140481*g56_1 + 0.026369336063687354*g143_1 + 0.04005567341841175*g205_1 + 0.030367471989795128*g23_1 + -0.035933461851340318*g184_1 + -0.29079322910948563*g55_1 + -0.0420162962847263*g180_1 + 0.021963392488271134*g181_1 + -0.021745426570983186*g32_1 + -0.061833146152835819*g28_1 + -0.13341226504240064*g96_1 + 0.0071882926711274919*g103_1 + 0.07602574900471111*g34_1 + 0.012657805485281514*g86_1 + 0.0072364649468001762*g100_1 + -0.072135956663836237*g201_1 + 0.29806953287768162*g29_1) + (0.38537540449817981*g187_1 + 0.037820975741386653*g37_1 + 0.0082265640016904139*g50_1 + -0.019752844154623275*g139_1 + 0.087952446184315039*g9_1 + 0.17181401619741479*g6_1 + -0.15136511005519163*g26_1 + 0.032875028408642148*g111_1 + -0.017894619352488653*g2_1 + -0.011243043887263993*g157_1 + 0.0046303233300942406*g19_1 + 0.043525414354558228*g8_1 + -0.0011805165034969643*g67_1 + -0.011196400450529087*g74_1 + 0.18398321247110488*g99_1 + -0.019201189893902165*g122_1 + 0.21046081675149847*g182_1 + 0.0060045850408073182*g68_1 + 0.01483394469900289*g91_1 + -0.060902233259077454*g166_1 + -0.20079600480014925*g183_1 + 0.032794210682105723*g83_1);
    std::memcpy(moment_arm + 979, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 985, &a1, 5 * sizeof(double)); L[89] = a0[6]; }
  { const v8d a0 = (0.26809586576800187*g_one_0 + 0.14141178550108993*g187_0 + 0.11959084492804571*g9_0 + 0.0045900629518303565*g105_0 + -0.024420235965576399*g25_0 + -0.035746446388249184*g55_0 + -0.0083438662963584726*g157_0 + -0.0095615116811232463*g95_0 + -0.037540745334056658*g94_0 + 0.077246284993672976*g34_0 + -0.084530625345037649*g166_0 + 0.0052066041028559079*g19_0 + 0.0011969933256209661*g181_0 + -0.20817770505248714*g54_0 + -0.016696633144504341*g110_0 + 0.023409429062285304*g156_0 + 0.0026268991144401659*g85_0 + -0.022859900525099411*g130_0 + 0.1149652821286087*g114_0 + -0.013770672928972291*g32_0 + 0.0063524668813630687*g144_0 + -0.028753137760582241*g111_0 + 0.057432314094357874*g6_0 + 0.013353675346567988*g107_0 + -0.054052835262718868*g188_0 + 0.0061016784380558851*g68_0 + -0.027589780080807969*g122_0 + 0.0072302111657606572*g72_0 + -0.010136890021869007*g146_0 + 0.0038929976512226323*g70_0 + 0.0022786690993160698*g151_0 + -0.025110229592485919*g184_0 + 0.035581787158863357*g129_0) + (0.0059544095480062809*g49_0 + 0.27185882599307853*g186_0 + 0.035701491186238235*g37_0 + 0.0016924146191513508*g139_0 + -0.024399774339639635*g143_0 + 0.038060309252089156*g142_0 + 0.039288282373700217*g23_0 + -0.042456376913130617*g200_0 + 0.23056086079466895*g56_0 + 0.044958802241994215*g3_0 + 0.051356956076088804*g93_0 + 0.049007929658879949*g8_0 + -0.018097248655271059*g104_0 + -0.14794582449258825*g113_0 + -0.0064317172963831446*g79_0 + -0.0069535931687665555*g196_0 + -0.048055358990872661*g96_0 + 0.053634318014300214*g136_0 + -0.0114480017549385*g74_0 + -0.023137971454861659*g2_0 + -0.01465049030433823*g185_0 + -0.052470893702186112*g180_0 + -0.085550501330687118*g164_0 + -0.014454098145716424*g31_0 + -0.010707292294855949*g190_0 + 0.02245148278521903*g86_0 + -0.0027755326028856995*g175_0 + -0.011360658270882597*g145_0 + 0.003517294511581007*g174_0 + -0.0051758337600619451*g76_0 + -0.023469202123975807*g87_0 + -0.0057352469338718742*g102_0 + 0.020731698117862511*g138_0); const v8d a1 = (0.26809586576800187*g_one_1 + 0.14141178550108993*g187_1 + 0.11959084492804571*g9_1 + 0.0045900629518303565*g105_1 + -0.024420235965576399*g25_1 + -0.035746446388249184*g55_1 + -0.0083438662963584726*g157_1 + -0.0095615116811232463*g95_1 + -0.037540745334056658*g94_1 + 0.077246284993672976*g34_1 + -0.084530625345037649*g166_1 + 0.0052066041028559079*g19_1 + 0.0011969933256209661*g181_1 + -0.20817770505248714*g54_1 + -0.016696633144504341*g110_1 + 0.023409429062285304*g156_1 + 0.0026268991144401659*g85_1 + -0.022859900525099411*g130_1 + 0.1149652821286087*g114_1 + -0.013770672928972291*g32_1 + 0.0063524668813630687*g144_1 + -0.028753137760582241*g111_1 + 0.057432314094357874*g6_1 + 0.013353675346567988*g107_1 + -0.054052835262718868*g188_1 + 0.0061016784380558851*g68_1 + -0.027589780080807969*g122_1 + 0.0072302111657606572*g72_1 + -0.010136890021869007*g146_1 + 0.0038929976512226323*g70_1 + 0.0022786690993160698*g151_1 + -0.025110229592485919*g184_1 + 0.035581787158863357*g129_1) + (0.0059544095480062809*g49_1 + 0.27185882599307853*g186_1 + 0.035701491186238235*g37_1 + 0.0016924146191513508*g139_1 + -0.024399774339639635*g143_1 + 0.038060309252089156*g142_1 + 0.039288282373700217*g23_1 + -0.042456376913130617*g200_1 + 0.23056086079466895*g56_1 + 0.044958802241994215*g3_1 + 0.051356956076088804*g93_1 + 0.049007929658879949*g8_1 + -0.018097248655271059*g104_1 + -0.14794582449258825*g113_1 + -0.0064317172963831446*g79_1 + -0.0069535931687665555*g196_1 + -0.048055358990872661*g96_1 + 0.053634318014300214*g136_1 + -0.0114480017549385*g74_1 + -0.023137971454861659*g2_1 + -0.01465049030433823*g185_1 + -0.052470893702186112*g180_1 + -0.085550501330687118*g164_1 + -0.014454098145716424*g31_1 + -0.010707292294855949*g190_1 + 0.02245148278521903*g86_1 + -0.0027755326028856995*g175_1 + -0.011360658270882597*g145_1 + 0.003517294511581007*g174_1 + -0.0051758337600619451*g76_1 + -0.023469202123975807*g87_1 + -0.0057352469338718742*g102_1 + 0.020731698117862511*g138_1);
    std::memcpy(moment_arm + 990, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 996, &a1, 5 * sizeof(double)); L[90] = a0[6]; }
  { const v8d a0 = (0.27380789037393094*g_one_0 + -0.050746952059409878*g187_0 + 0.062797952956876069*g37_0 + 0.047179997373018548*g23_0 + -0.036036162456450978*g166_0 + -0.049595565756853456*g143_0 + -0.1137711766398789*g132_0 + -0.014241010053607546*g117_0 + -0.0647576472702492*g205_0 + 0.00096680054839562825*g134_0 + -0.0099818768802558376*g112_0 + -0.073388047586367897*g40_0 + 0.033700769453792113*g177_0 + 0.06029772725947654*g150_0 + -0.21261088337906911*g204_0 + -0.14807532877800456*g55_0 + -0.028699363999174516*g29_0 + -0.017257198803331715*g196_0 + 0.035781608634308119*g47_0 + 0.03912802210586229*g26_0 + 0.032422369961776602*g111_0 + 0.0069553310057331478*g155_0 + 0.011093778311898145*g129_0 + -0.017916844434069559*g148_0) + (0.16230129893433962*g9_0 + 0.17968192915920209*g186_0 + 0.0039127526136854647*g139_0 + -0.016383523636123699*g2_0 + 0.028136811614356091*g199_0 + -0.027681553946685651*g157_0 + 0.078781139770455283*g209_0 + -0.31009747590317521*g54_0 + 0.043776466089341513*g3_0 + -0.048203594347739243*g92_0 + -0.0012516235195693432*g19_0 + -0.0072818933103604173*g168_0 + -0.006613352634300863*g74_0 + -0.012085350210995134*g76_0 + -0.018833060875909302*g35_0 + -0.18154081736179667*g183_0 + 0.0065538624255456418*g103_0 + -0.04079191187068041*g87_0 + -0.0096347109092595716*g145_0 + -0.03351543617567268*g122_0 + 0.040982526477268369*g56_0 + 0.043617310187711839*g93_0 + 0.056919480011987621*g42_0); const v8d a1 = (0.27380789037393094*g_one_1 + -0.050746952059409878*g187_1 + 0.062797952956876069*g37_1 + 0.047179997373018548*g23_1 + -0.036036162456450978*g166_1 + -0.049595565756853456*g143_1 + -0.1137711766398789*g132_1 + -0.014241010053607546*g117_1 + -0.0647576472702492*g205_1 + 0.00096680054839562825*g134_1 + -0.0099818768802558376*g112_1 + -0.073388047586367897*g40_1 + 0.033700769453792113*g177_1 + 0.06029772725947654*g150_1 + -0.21261088337906911*g204_1 + -0.14807532877800456*g55_1 + -0.028699363999174516*g29_1 + -0.017257198803331715*g196_1 + 0.035781608634308119*g47_1 + 0.03912802210586229*g26_1 + 0.032422369961776602*g111_1 + 0.0069553310057331478*g155_1 + 0.011093778311898145*g129_1 + -0.017916844434069559*g148_1) + (0.16230129893433962*g9_1 + 0.17968192915920209*g186_1 + 0.0039127526136854647*g139_1 + -0.016383523636123699*g2_1 + 0.028136811614356091*g199_1 + -0.027681553946685651*g157_1 + 0.078781139770455283*g209_1 + -0.31009747590317521*g54_1 + 0.043776466089341513*g3_1 + -0.048203594347739243*g92_1 + -0.0012516235195693432*g19_1 + -0.0072818933103604173*g168_1 + -0.006613352634300863*g74_1 + -0.012085350210995134*g76_1 + -0.018833060875909302*g35_1 + -0.18154081736179667*g183_1 + 0.0065538624255456418*g103_1 + -0.04079191187068041*g87_1 + -0.0096347109092595716*g145_1 + -0.03351543617567268*g122_1 + 0.040982526477268369*g56_1 + 0.043617310187711839*g93_1 + 0.056919480011987621*g42_1);
    std::memcpy(moment_arm + 1001, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1007, &a1, 5 * sizeof(double)); L[91] = a0[6]; }
  { const v8d a0 = (0.30205064206349058*g_one_0 + -0.020654184981658698*g186_0 + 0.060802119627081527*g37_0 + 0.017626212012656885*g167_0 + -0.0053618749314973202*g18_0 + 0.036386337782999878*g23_0 + 0.057756863705452847*g42_0 + 0.010417931840766248*g111_0 + -0.0042660753268686236*g203_0 + 0.018715856775837189*g181_0 + -0.05760324451582606*g143_0 + -0.050944246700626979*g154_0 + -0.18818240919743309*g183_0 + 0.022084007315803501*g114_0 + 0.018840756225382223*g48_0 + -0.01301039148743123*g76_0 + 0.078061650610512276*g98_0 + 0.028976704031711691*g189_0 + -0.053422796285825504*g172_0 + -0.015862153349754823*g120_0 + -0.034240282187758819*g87_0 + 0.026153459137793978*g82_0 + 0.046038948355412397*g26_0 + -0.042403877484128612*g202_0 + -0.0046417174088724178*g145_0 + 0.0091051875291757092*g80_0) + (0.16197200254874389*g9_0 + -5.1064315841509418e-05*g159_0 + -0.1468871336651511*g55_0 + -0.02993994708069353*g157_0 + -0.002520200244796972*g152_0 + 0.040545004987935708*g3_0 + -0.0077245663751167671*g174_0 + -0.033321255774212154*g16_0 + -0.013004961974468076*g104_0 + 0.014620494270138295*g68_0 + -0.10268859788182223*g171_0 + 0.056372896561352789*g50_0 + 0.028444586528623503*g33_0 + -0.017970419232977583*g125_0 + -0.039752186821750496*g113_0 + 0.048163242577651574*g93_0 + 0.0077082194726421378*g139_0 + 0.012727811049088962*g103_0 + -0.06665862308849145*g92_0 + 0.049522330732484292*g150_0 + -0.032962251289419542*g122_0 + 0.03539345599272286*g10_0 + 0.013083167910684947*g124_0 + 0.019033721809806822*g161_0 + -0.010923396043234302*g81_0); const v8d a1 = (0.30205064206349058*g_one_1 + -0.020654184981658698*g186_1 + 0.060802119627081527*g37_1 + 0.017626212012656885*g167_1 + -0.0053618749314973202*g18_1 + 0.036386337782999878*g23_1 + 0.057756863705452847*g42_1 + 0.010417931840766248*g111_1 + -0.0042660753268686236*g203_1 + 0.018715856775837189*g181_1 + -0.05760324451582606*g143_1 + -0.050944246700626979*g154_1 + -0.18818240919743309*g183_1 + 0.022084007315803501*g114_1 + 0.018840756225382223*g48_1 + -0.01301039148743123*g76_1 + 0.078061650610512276*g98_1 + 0.028976704031711691*g189_1 + -0.053422796285825504*g172_1 + -0.015862153349754823*g120_1 + -0.034240282187758819*g87_1 + 0.026153459137793978*g82_1 + 0.046038948355412397*g26_1 + -0.042403877484128612*g202_1 + -0.0046417174088724178*g145_1 + 0.0091051875291757092*g80_1) + (0.16197200254874389*g9_1 + -5.1064315841509418e-05*g159_1 + -0.1468871336651511*g55_1 + -0.02993994708069353*g157_1 + -0.002520200244796972*g152_1 + 0.040545004987935708*g3_1 + -0.0077245663751167671*g174_1 + -0.033321255774212154*g16_1 + -0.013004961974468076*g104_1 + 0.014620494270138295*g68_1 + -0.10268859788182223*g171_1 + 0.056372896561352789*g50_1 + 0.028444586528623503*g33_1 + -0.017970419232977583*g125_1 + -0.039752186821750496*g113_1 + 0.048163242577651574*g93_1 + 0.0077082194726421378*g139_1 + 0.012727811049088962*g103_1 + -0.06665862308849145*g92_1 + 0.049522330732484292*g150_1 + -0.032962251289419542*g122_1 + 0.03539345599272286*g10_1 + 0.013083167910684947*g124_1 + 0.019033721809806822*g161_1 + -0.010923396043234302*g81_1);
    std::memcpy(moment_arm + 1012, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1018, &a1, 5 * sizeof(double)); L[92] = a0[6]; }
  { const v8d a0 = (0.27322441186141644*g_one_0 + 0.0022972919321589194*g186_0 + 0.082238219468715637*g159_0 + -0.0030338978252454434*g146_0 + -0.015524746352878921*g96_0 + 0.020559640580787766*g80_0 + 0.032042628529592367*g97_0 + -0.044662677332594318*g157_0 + -0.027380289079679442*g106_0 + -0.0051381740299417692*g4_0 + 0.059570165619767884*g10_0 + -0.093253488440756788*g172_0 + -0.032393480790344729*g36_0 + 0.039206282602889796*g138_0 + -0.069592064291228911*g193_0 + -0.011867521531197205*g76_0 + -0.048080767113769879*g170_0 + -0.021177045751887079*g87_0) + (0.19434383976040295*g9_0 + 0.05809760519103601*g37_0 + 0.043881801977224764*g17_0 + -0.0085756783480087986*g2_0 + -0.012249084313570481*g102_0 + -0.0081468678701885674*g196_0 + -0.013530303001490419*g69_0 + 0.056470838427241321*g42_0 + 0.017757386195620062*g77_0 + 0.050363869661745664*g94_0 + 0.070315331126031569*g33_0 + -0.0070608396984480652*g184_0 + -0.057783600513081929*g139_0 + -0.081557070027910447*g164_0 + -0.072709191880203361*g205_0 + -0.025501418527729532*g197_0 + -0.0270178549834835*g180_0 + 0.042174468365493441*g26_0); const v8d a1 = (0.27322441186141644*g_one_1 + 0.0022972919321589194*g186_1 + 0.082238219468715637*g159_1 + -0.0030338978252454434*g146_1 + -0.015524746352878921*g96_1 + 0.020559640580787766*g80_1 + 0.032042628529592367*g97_1 + -0.044662677332594318*g157_1 + -0.027380289079679442*g106_1 + -0.0051381740299417692*g4_1 + 0.059570165619767884*g10_1 + -0.093253488440756788*g172_1 + -0.032393480790344729*g36_1 + 0.039206282602889796*g138_1 + -0.069592064291228911*g193_1 + -0.011867521531197205*g76_1 + -0.048080767113769879*g170_1 + -0.021177045751887079*g87_1) + (0.19434383976040295*g9_1 + 0.05809760519103601*g37_1 + 0.043881801977224764*g17_1 + -0.0085756783480087986*g2_1 + -0.012249084313570481*g102_1 + -0.0081468678701885674*g196_1 + -0.013530303001490419*g69_1 + 0.056470838427241321*g42_1 + 0.017757386195620062*g77_1 + 0.050363869661745664*g94_1 + 0.070315331126031569*g33_1 + -0.0070608396984480652*g184_1 + -0.057783600513081929*g139_1 + -0.081557070027910447*g164_1 + -0.072709191880203361*g205_1 + -0.025501418527729532*g197_1 + -0.0270178549834835*g180_1 + 0.042174468365493441*g26_1);
    std::memcpy(moment_arm + 1023, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1029, &a1, 5 * sizeof(double)); L[93] = a0[6]; }
  { const v8d a0 = (0.24342738933662672*g_one_0 + -0.067417577435197162*g186_0 + 0.034173670894453355*g159_0 + -0.04208002127329169*g149_0 + 0.0029669607333162743*g2_0 + -0.010638423660878639*g69_0 + 0.036925141817662384*g97_0 + -0.053174180805637093*g92_0 + -0.011019835771213592*g78_0 + -0.13459597329681111*g182_0 + -0.013032871883002029*g76_0 + -0.03133928782112045*g36_0 + -0.053566781622679589*g44_0 + -0.0067487658284399272*g39_0 + 0.23083763415446371*g154_0 + 0.061180949737589911*g10_0 + -0.15610946272734774*g151_0 + 0.047444508730976873*g5_0 + -0.059785552684891823*g96_0 + 0.013329036240788536*g179_0 + -0.040720448562330452*g195_0) + (0.28358253333895289*g9_0 + 0.09416607199701453*g37_0 + 0.041220459156435768*g17_0 + -0.0044384106910860064*g202_0 + -0.0015273929646073678*g111_0 + 0.029041382016671398*g80_0 + -0.060957004252822383*g157_0 + 0.0049583195787779024*g184_0 + -0.025231764745325059*g16_0 + -0.038083563837037253*g162_0 + 0.020984948151926964*g49_0 + 0.010690767032428029*g68_0 + 0.037886567203339237*g138_0 + 0.0080426905793870209*g23_0 + 0.0050037391093440053*g102_0 + 0.039626376854282545*g59_0 + 0.32179997773263841*g47_0 + -0.1056144860376049*g193_0 + -0.034660999943234676*g122_0 + -0.019329866657133713*g116_0); const v8d a1 = (0.24342738933662672*g_one_1 + -0.067417577435197162*g186_1 + 0.034173670894453355*g159_1 + -0.04208002127329169*g149_1 + 0.0029669607333162743*g2_1 + -0.010638423660878639*g69_1 + 0.036925141817662384*g97_1 + -0.053174180805637093*g92_1 + -0.011019835771213592*g78_1 + -0.13459597329681111*g182_1 + -0.013032871883002029*g76_1 + -0.03133928782112045*g36_1 + -0.053566781622679589*g44_1 + -0.0067487658284399272*g39_1 + 0.23083763415446371*g154_1 + 0.061180949737589911*g10_1 + -0.15610946272734774*g151_1 + 0.047444508730976873*g5_1 + -0.059785552684891823*g96_1 + 0.013329036240788536*g179_1 + -0.040720448562330452*g195_1) + (0.28358253333895289*g9_1 + 0.09416607199701453*g37_1 + 0.041220459156435768*g17_1 + -0.0044384106910860064*g202_1 + -0.0015273929646073678*g111_1 + 0.029041382016671398*g80_1 + -0.060957004252822383*g157_1 + 0.0049583195787779024*g184_1 + -0.025231764745325059*g16_1 + -0.038083563837037253*g162_1 + 0.020984948151926964*g49_1 + 0.010690767032428029*g68_1 + 0.037886567203339237*g138_1 + 0.0080426905793870209*g23_1 + 0.0050037391093440053*g102_1 + 0.039626376854282545*g59_1 + 0.32179997773263841*g47_1 + -0.1056144860376049*g193_1 + -0.034660999943234676*g122_1 + -0.019329866657133713*g116_1);
    std::memcpy(moment_arm + 1034, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1040, &a1, 5 * sizeof(double)); L[94] = a0[6]; }
  { const v8d a0 = (0.14205335811909309*g_one_0 + 0.13128383899479446*g159_0 + -0.028655565306369923*g4_0 + 0.016370726631750859*g142_0 + -0.11067883868450465*g99_0 + 0.013426319520355261*g184_0 + -0.026960346868781255*g2_0 + -0.097735871373020894*g33_0 + 0.02381496362259012*g17_0 + 0.016564801890557864*g93_0 + -0.043153030659750131*g31_0 + -0.047289561071014632*g106_0 + 0.010762123324095827*g37_0 + 0.12750131707357157*g107_0 + -0.0065009932587878766*g88_0 + -0.021610821337989444*g90_0 + 0.018723940471862835*g86_0 + 0.031002837278597355*g72_0 + -0.039797114345468808*g19_0 + -0.29082419267020132*g170_0 + 0.040519810257043938*g42_0 + 0.057240193294475071*g3_0 + 0.15778547220116734*g134_0 + 0.026024509609593724*g32_0 + -0.0056321928990359814*g176_0 + 0.0063694463756601644*g121_0 + -0.063226454771587268*g182_0 + 0.0062176024682245572*g89_0 + -0.01765445083329702*g71_0 + 0.0041605071056477587*g68_0 + 0.057598612132199412*g6_0) + (0.20334486561357784*g9_0 + 0.0064605784120561052*g52_0 + -0.03304352285028675*g139_0 + 0.0016412687693001908*g196_0 + 0.11297415885338835*g209_0 + -0.0094138602564988946*g69_0 + -0.021468221166088087*g78_0 + 0.030326178656457863*g80_0 + -0.058132156028920919*g29_0 + 0.14461703597198219*g59_0 + -0.22252095841895542*g132_0 + -0.03144359001286167*g104_0 + -0.1024735334662859*g137_0 + 0.05460165179575955*g126_0 + -0.061046227770933319*g41_0 + 0.0069564724754003033*g15_0 + 0.010024646171043592*g108_0 + -0.014457193406591008*g147_0 + -0.01426440910397872*g173_0 + -0.18564387201487573*g136_0 + 0.024135533603145694*g95_0 + 0.052601095266088756*g163_0 + -0.033148298440091692*g122_0 + 0.00070001500672632697*g185_0 + -0.1253382662663956*g50_0 + -0.07341883766297097*g199_0 + -0.088167432601488224*g153_0 + -0.013327288682848748*g146_0 + 0.018861022664832534*g18_0 + 0.019306784746095804*g191_0); const v8d a1 = (0.14205335811909309*g_one_1 + 0.13128383899479446*g159_1 + -0.028655565306369923*g4_1 + 0.016370726631750859*g142_1 + -0.11067883868450465*g99_1 + 0.013426319520355261*g184_1 + -0.026960346868781255*g2_1 + -0.097735871373020894*g33_1 + 0.02381496362259012*g17_1 + 0.016564801890557864*g93_1 + -0.043153030659750131*g31_1 + -0.047289561071014632*g106_1 + 0.010762123324095827*g37_1 + 0.12750131707357157*g107_1 + -0.0065009932587878766*g88_1 + -0.021610821337989444*g90_1 + 0.018723940471862835*g86_1 + 0.031002837278597355*g72_1 + -0.039797114345468808*g19_1 + -0.29082419267020132*g170_1 + 0.040519810257043938*g42_1 + 0.057240193294475071*g3_1 + 0.15778547220116734*g134_1 + 0.026024509609593724*g32_1 + -0.0056321928990359814*g176_1 + 0.0063694463756601644*g121_1 + -0.063226454771587268*g182_1 + 0.0062176024682245572*g89_1 + -0.01765445083329702*g71_1 + 0.0041605071056477587*g68_1 + 0.057598612132199412*g6_1) + (0.20334486561357784*g9_1 + 0.0064605784120561052*g52_1 + -0.03304352285028675*g139_1 + 0.0016412687693001908*g196_1 + 0.11297415885338835*g209_1 + -0.0094138602564988946*g69_1 + -0.021468221166088087*g78_1 + 0.030326178656457863*g80_1 + -0.058132156028920919*g29_1 + 0.14461703597198219*g59_1 + -0.22252095841895542*g132_1 + -0.03144359001286167*g104_1 + -0.1024735334662859*g137_1 + 0.05460165179575955*g126_1 + -0.061046227770933319*g41_1 + 0.0069564724754003033*g15_1 + 0.010024646171043592*g108_1 + -0.014457193406591008*g147_1 + -0.01426440910397872*g173_1 + -0.18564387201487573*g136_1 + 0.024135533603145694*g95_1 + 0.052601095266088756*g163_1 + -0.033148298440091692*g122_1 + 0.00070001500672632697*g185_1 + -0.1253382662663956*g50_1 + -0.07341883766297097*g199_1 + -0.088167432601488224*g153_1 + -0.013327288682848748*g146_1 + 0.018861022664832534*g18_1 + 0.019306784746095804*g191_1);
    std::memcpy(moment_arm + 1045, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1051, &a1, 5 * sizeof(double)); L[95] = a0[6]; }
  { const v8d a0 = (0.17399930510855097*g_one_0 + -0.0042928539893308994*g34_0 + 0.01493666083818111*g44_0 + -0.025777848855515727*g122_0 + -0.013627860603240246*g204_0 + -0.029065436836253587*g2_0 + -0.0425838635742887*g83_0 + 0.17629879914906008*g29_0 + -0.013358000444046201*g76_0 + 0.020148164503905421*g98_0 + -0.031301828237399153*g23_0 + 0.09944139319182578*g3_0 + 0.13002019411102489*g9_0 + 0.023935653022723064*g30_0 + 0.0028946627753041075*g112_0 + -0.0401924399284595*g19_0 + 0.01567639590581443*g103_0 + 0.24656124428422019*g109_0 + 0.088316800551861543*g99_0 + -0.021624044340302479*g133_0 + 0.022680175058223367*g124_0 + 0.18304529759551186*g135_0 + -0.013206808923825787*g101_0 + -0.0066974020106767614*g123_0 + 0.055721040030181433*g134_0 + 0.0058122252777966319*g73_0 + -0.021662127853021566*g90_0 + -0.0012143633864384142*g108_0 + -0.015392047645937081*g79_0 + 0.0047276489390995265*g70_0 + 0.0051604072679022018*g68_0 + 0.014443353285760857*g117_0 + -0.0348513943980511*g151_0 + 0.13989104735000932*g6_0 + -0.021443332206236981*g87_0) + (-0.0073150009470484608*g58_0 + -0.025768781739386029*g4_0 + -0.004195754037150657*g156_0 + 0.029226965366684739*g196_0 + -0.083390059300542677*g132_0 + 0.037689502166074133*g80_0 + -0.018953589951624338*g168_0 + -0.0055982185849337354*g173_0 + 0.0015103702815797734*g52_0 + -0.021801796803906367*g116_0 + -0.010617967387033465*g148_0 + -0.035102982250632762*g104_0 + -0.045893790903468734*g10_0 + -0.12147296378505892*g140_0 + 0.029252569472339354*g72_0 + -0.0098403937008805925*g145_0 + -0.095192313962264907*g82_0 + -0.059781643647533966*g141_0 + -0.078095931434769408*g31_0 + -0.013024305331775165*g160_0 + 0.031423940797455689*g37_0 + -0.016208656620780384*g163_0 + 0.011125564555284111*g121_0 + -0.014142914743660242*g17_0 + -0.015256377949007461*g71_0 + -0.0097102219879656761*g125_0 + -0.0071633622054144705*g74_0 + -0.029157875423480802*g42_0 + 0.0018964991075765757*g66_0 + 0.03092062556330416*g102_0 + -0.0048671716538206027*g69_0 + 0.0069824248586569685*g89_0 + -0.05207827244887319*g154_0 + -0.054291879837950585*g96_0); const v8d a1 = (0.17399930510855097*g_one_1 + -0.0042928539893308994*g34_1 + 0.01493666083818111*g44_1 + -0.025777848855515727*g122_1 + -0.013627860603240246*g204_1 + -0.029065436836253587*g2_1 + -0.0425838635742887*g83_1 + 0.17629879914906008*g29_1 + -0.013358000444046201*g76_1 + 0.020148164503905421*g98_1 + -0.031301828237399153*g23_1 + 0.09944139319182578*g3_1 + 0.13002019411102489*g9_1 + 0.023935653022723064*g30_1 + 0.0028946627753041075*g112_1 + -0.0401924399284595*g19_1 + 0.01567639590581443*g103_1 + 0.24656124428422019*g109_1 + 0.088316800551861543*g99_1 + -0.021624044340302479*g133_1 + 0.022680175058223367*g124_1 + 0.18304529759551186*g135_1 + -0.013206808923825787*g101_1 + -0.0066974020106767614*g123_1 + 0.055721040030181433*g134_1 + 0.0058122252777966319*g73_1 + -0.021662127853021566*g90_1 + -0.0012143633864384142*g108_1 + -0.015392047645937081*g79_1 + 0.0047276489390995265*g70_1 + 0.0051604072679022018*g68_1 + 0.014443353285760857*g117_1 + -0.0348513943980511*g151_1 + 0.13989104735000932*g6_1 + -0.021443332206236981*g87_1) + (-0.0073150009470484608*g58_1 + -0.025768781739386029*g4_1 + -0.004195754037150657*g156_1 + 0.029226965366684739*g196_1 + -0.083390059300542677*g132_1 + 0.037689502166074133*g80_1 + -0.018953589951624338*g168_1 + -0.0055982185849337354*g173_1 + 0.0015103702815797734*g52_1 + -0.021801796803906367*g116_1 + -0.010617967387033465*g148_1 + -0.035102982250632762*g104_1 + -0.045893790903468734*g10_1 + -0.12147296378505892*g140_1 + 0.029252569472339354*g72_1 + -0.0098403937008805925*g145_1 + -0.095192313962264907*g82_1 + -0.059781643647533966*g141_1 + -0.078095931434769408*g31_1 + -0.013024305331775165*g160_1 + 0.031423940797455689*g37_1 + -0.016208656620780384*g163_1 + 0.011125564555284111*g121_1 + -0.014142914743660242*g17_1 + -0.015256377949007461*g71_1 + -0.0097102219879656761*g125_1 + -0.0071633622054144705*g74_1 + -0.029157875423480802*g42_1 + 0.0018964991075765757*g66_1 + 0.03092062556330416*g102_1 + -0.0048671716538206027*g69_1 + 0.0069824248586569685*g89_1 + -0.05207827244887319*g154_1 + -0.054291879837950585*g96_1);
    std::memcpy(moment_arm + 1056, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1062, &a1, 5 * sizeof(double)); L[96] = a0[6]; }
  { const v8d a0 = (0.23016960276061904*g_one_0 + 0.38381652622379631*g34_0 + 0.025540735856188556*g44_0 + -0.020607157159906124*g4_0 + 0.10799605744017826*g6_0 + -0.08528947205644094*g168_0 + -0.019340273103569779*g2_0 + -0.2898221044618508*g26_0 + -0.084921531922446641*g119_0 + 0.099463785923085607*g202_0 + -0.23313497806478906*g96_0 + -0.022870194858989883*g108_0 + 0.033456109943596969*g50_0 + -0.042218669501847481*g195_0 + -0.0053866766834018195*g83_0 + -0.040510150114774671*g19_0 + 0.11884550695227905*g99_0 + -0.017029883863684307*g5_0 + -0.09372007127116011*g92_0 + -0.03280952018518498*g10_0 + 0.067160340237348556*g37_0 + 0.18681845974852521*g113_0) + (-0.027934247557632515*g58_0 + -0.038387981292583723*g104_0 + -0.031357478479735072*g178_0 + -6.2437820899302024e-05*g156_0 + -0.023032096130210081*g122_0 + 0.012763004929741629*g78_0 + -0.082749919560356086*g192_0 + 0.082721308160204315*g173_0 + 0.031443298679452461*g80_0 + -0.026702563945751882*g106_0 + 0.11411418300444737*g111_0 + 0.52936847082006511*g114_0 + 0.012422945260859089*g70_0 + 0.032520442192566688*g72_0 + -0.010431008005317636*g127_0 + -0.015805490281383606*g74_0 + 0.010916273242208903*g186_0 + 0.016726597306009384*g105_0 + 0.088641265350052456*g9_0 + -0.073002963990930092*g132_0 + -0.032963760409325492*g41_0); const v8d a1 = (0.23016960276061904*g_one_1 + 0.38381652622379631*g34_1 + 0.025540735856188556*g44_1 + -0.020607157159906124*g4_1 + 0.10799605744017826*g6_1 + -0.08528947205644094*g168_1 + -0.019340273103569779*g2_1 + -0.2898221044618508*g26_1 + -0.084921531922446641*g119_1 + 0.099463785923085607*g202_1 + -0.23313497806478906*g96_1 + -0.022870194858989883*g108_1 + 0.033456109943596969*g50_1 + -0.042218669501847481*g195_1 + -0.0053866766834018195*g83_1 + -0.040510150114774671*g19_1 + 0.11884550695227905*g99_1 + -0.017029883863684307*g5_1 + -0.09372007127116011*g92_1 + -0.03280952018518498*g10_1 + 0.067160340237348556*g37_1 + 0.18681845974852521*g113_1) + (-0.027934247557632515*g58_1 + -0.038387981292583723*g104_1 + -0.031357478479735072*g178_1 + -6.2437820899302024e-05*g156_1 + -0.023032096130210081*g122_1 + 0.012763004929741629*g78_1 + -0.082749919560356086*g192_1 + 0.082721308160204315*g173_1 + 0.031443298679452461*g80_1 + -0.026702563945751882*g106_1 + 0.11411418300444737*g111_1 + 0.52936847082006511*g114_1 + 0.012422945260859089*g70_1 + 0.032520442192566688*g72_1 + -0.010431008005317636*g127_1 + -0.015805490281383606*g74_1 + 0.010916273242208903*g186_1 + 0.016726597306009384*g105_1 + 0.088641265350052456*g9_1 + -0.073002963990930092*g132_1 + -0.032963760409325492*g41_1);
    std::memcpy(moment_arm + 1067, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1073, &a1, 5 * sizeof(double)); L[97] = a0[6]; }
  { const v8d a0 = (0.15652852825421282*g_one_0 + -0.0032579122774317199*g58_0 + 0.0010579518353968113*g109_0 + -0.030486383904389437*g17_0 + 0.10266741584449583*g9_0 + 0.034563881694761538*g102_0 + -0.029432579804754961*g2_0 + -0.08358007660964567*g128_0 + -0.039504147971808429*g19_0 + -0.047144093730721558*g106_0 + 0.0082970374551820259*g100_0 + -0.10806648330969204*g118_0 + 0.013831198490873409*g103_0 + 0.011468797379041933*g129_0 + -0.017597581960853922*g108_0 + -0.010818635989610878*g74_0 + 0.0080344085268677264*g75_0 + -0.012373895123995842*g130_0 + -0.078519232417170057*g170_0 + 0.013373805697590094*g196_0 + 0.015913410235822739*g86_0 + -0.0060426873138844286*g38_0 + 0.0056932448680401225*g70_0 + 0.0033702779072039713*g68_0 + 0.037716657245698372*g26_0 + -0.017273436616926839*g90_0 + -0.010903237642236384*g101_0 + 0.013928841133566808*g16_0 + 0.0097750908451346274*g18_0 + 0.097369669241528706*g119_0 + 0.027162992554655652*g134_0) + (-0.041193394730944619*g34_0 + -0.031832725227757444*g104_0 + -0.014167191821212718*g4_0 + 0.08888529134001262*g107_0 + -0.041296155948225971*g10_0 + -0.055826788292697362*g29_0 + -0.013042789665114853*g139_0 + 0.093044107042165453*g3_0 + -0.065077143817337313*g116_0 + 0.027654475196806725*g72_0 + -0.076414126277744576*g171_0 + 0.023603241276936426*g80_0 + -0.02358421035261548*g127_0 + -0.0043258862371967433*g88_0 + -0.0054971763345159933*g69_0 + 0.022674165990653576*g105_0 + -0.017068416885955059*g169_0 + -0.079547732594700257*g154_0 + 0.026114669044355766*g132_0 + -0.065686808053955395*g141_0 + 0.011669203501884372*g124_0 + -0.023543493903506938*g20_0 + -0.0048807626199644516*g123_0 + -0.026700426879179309*g87_0 + -0.013256610348608196*g25_0 + 0.018862167331982975*g112_0 + -0.016426928661265178*g71_0 + 0.066939134124586339*g113_0 + 0.01506931411232347*g21_0 + 0.070492902994925527*g40_0 + 0.037514106611963929*g24_0); const v8d a1 = (0.15652852825421282*g_one_1 + -0.0032579122774317199*g58_1 + 0.0010579518353968113*g109_1 + -0.030486383904389437*g17_1 + 0.10266741584449583*g9_1 + 0.034563881694761538*g102_1 + -0.029432579804754961*g2_1 + -0.08358007660964567*g128_1 + -0.039504147971808429*g19_1 + -0.047144093730721558*g106_1 + 0.0082970374551820259*g100_1 + -0.10806648330969204*g118_1 + 0.013831198490873409*g103_1 + 0.011468797379041933*g129_1 + -0.017597581960853922*g108_1 + -0.010818635989610878*g74_1 + 0.0080344085268677264*g75_1 + -0.012373895123995842*g130_1 + -0.078519232417170057*g170_1 + 0.013373805697590094*g196_1 + 0.015913410235822739*g86_1 + -0.0060426873138844286*g38_1 + 0.0056932448680401225*g70_1 + 0.0033702779072039713*g68_1 + 0.037716657245698372*g26_1 + -0.017273436616926839*g90_1 + -0.010903237642236384*g101_1 + 0.013928841133566808*g16_1 + 0.0097750908451346274*g18_1 + 0.097369669241528706*g119_1 + 0.027162992554655652*g134_1) + (-0.041193394730944619*g34_1 + -0.031832725227757444*g104_1 + -0.014167191821212718*g4_1 + 0.08888529134001262*g107_1 + -0.041296155948225971*g10_1 + -0.055826788292697362*g29_1 + -0.013042789665114853*g139_1 + 0.093044107042165453*g3_1 + -0.065077143817337313*g116_1 + 0.027654475196806725*g72_1 + -0.076414126277744576*g171_1 + 0.023603241276936426*g80_1 + -0.02358421035261548*g127_1 + -0.0043258862371967433*g88_1 + -0.0054971763345159933*g69_1 + 0.022674165990653576*g105_1 + -0.017068416885955059*g169_1 + -0.079547732594700257*g154_1 + 0.026114669044355766*g132_1 + -0.065686808053955395*g141_1 + 0.011669203501884372*g124_1 + -0.023543493903506938*g20_1 + -0.0048807626199644516*g123_1 + -0.026700426879179309*g87_1 + -0.013256610348608196*g25_1 + 0.018862167331982975*g112_1 + -0.016426928661265178*g71_1 + 0.066939134124586339*g113_1 + 0.01506931411232347*g21_1 + 0.070492902994925527*g40_1 + 0.037514106611963929*g24_1);
    std::memcpy(moment_arm + 1078, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1084, &a1, 5 * sizeof(double)); L[98] = a0[6]; }
  { const v8d a0 = (0.17931259646195014*g_one_0 + 0.010249167994692138*g186_0 + 0.094847914913233522*g9_0 + 0.034490321313164214*g114_0 + -0.084268544745493071*g158_0 + 0.066276020284432635*g3_0 + -0.043319377904569772*g116_0 + -0.022172387015323869*g106_0 + -0.015215171953841998*g192_0 + 0.017317426511097033*g103_0 + -0.021254314511078672*g10_0 + -0.074197893509806961*g29_0 + -0.001158558370587824*g69_0 + -0.18630467129700329*g48_0 + 0.062107547129364393*g135_0 + 0.017873306153709554*g105_0 + -0.0016928637355437387*g77_0 + -0.02629614156452742*g17_0 + 0.023390524460286929*g111_0 + 0.0063583403549352943*g70_0 + 0.0045065669732545837*g89_0 + 0.0061748905461301018*g73_0 + -0.014938301967616831*g20_0 + 0.0067992829571898858*g75_0 + 0.014286941130493759*g16_0 + -0.004287811347781079*g101_0) + (0.044238535272902453*g119_0 + -0.017650933249693041*g4_0 + 0.10700788283874027*g160_0 + 0.063910381811964984*g84_0 + -0.026945385526384123*g2_0 + -0.029429291173551902*g19_0 + 0.0085639314583558258*g100_0 + 0.012699395866012882*g78_0 + 0.012534357855738776*g134_0 + 0.22766777456130541*g109_0 + -0.02044185830796379*g87_0 + 0.020966648777232953*g72_0 + -0.025321153240349337*g104_0 + -0.044683793988595739*g82_0 + -0.011017137727897006*g74_0 + 0.0079174388153931529*g129_0 + -0.077513887200426734*g153_0 + 0.015734875266769189*g102_0 + -0.014780002927040022*g71_0 + 1.1523284196392429e-05*g121_0 + 0.0069768509088195966*g83_0 + 0.0010000181625988602*g68_0 + -0.018636409567298576*g141_0 + 0.0094950309130628231*g86_0 + 0.0062284349974431096*g95_0); const v8d a1 = (0.17931259646195014*g_one_1 + 0.010249167994692138*g186_1 + 0.094847914913233522*g9_1 + 0.034490321313164214*g114_1 + -0.084268544745493071*g158_1 + 0.066276020284432635*g3_1 + -0.043319377904569772*g116_1 + -0.022172387015323869*g106_1 + -0.015215171953841998*g192_1 + 0.017317426511097033*g103_1 + -0.021254314511078672*g10_1 + -0.074197893509806961*g29_1 + -0.001158558370587824*g69_1 + -0.18630467129700329*g48_1 + 0.062107547129364393*g135_1 + 0.017873306153709554*g105_1 + -0.0016928637355437387*g77_1 + -0.02629614156452742*g17_1 + 0.023390524460286929*g111_1 + 0.0063583403549352943*g70_1 + 0.0045065669732545837*g89_1 + 0.0061748905461301018*g73_1 + -0.014938301967616831*g20_1 + 0.0067992829571898858*g75_1 + 0.014286941130493759*g16_1 + -0.004287811347781079*g101_1) + (0.044238535272902453*g119_1 + -0.017650933249693041*g4_1 + 0.10700788283874027*g160_1 + 0.063910381811964984*g84_1 + -0.026945385526384123*g2_1 + -0.029429291173551902*g19_1 + 0.0085639314583558258*g100_1 + 0.012699395866012882*g78_1 + 0.012534357855738776*g134_1 + 0.22766777456130541*g109_1 + -0.02044185830796379*g87_1 + 0.020966648777232953*g72_1 + -0.025321153240349337*g104_1 + -0.044683793988595739*g82_1 + -0.011017137727897006*g74_1 + 0.0079174388153931529*g129_1 + -0.077513887200426734*g153_1 + 0.015734875266769189*g102_1 + -0.014780002927040022*g71_1 + 1.1523284196392429e-05*g121_1 + 0.0069768509088195966*g83_1 + 0.0010000181625988602*g68_1 + -0.018636409567298576*g141_1 + 0.0094950309130628231*g86_1 + 0.0062284349974431096*g95_1);
    std::memcpy(moment_arm + 1089, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1095, &a1, 5 * sizeof(double)); L[99] = a0[6]; }
  { const v8d a0 = (0.1875787988003966*g_one_0 + 0.061174961720337553*g109_0 + -0.069891039938441799*g99_0 + -0.15319060491845135*g29_0 + 0.11307635299371725*g3_0 + -0.1135828560856879*g31_0 + -0.018891764382224178*g2_0 + -0.013299197818906027*g58_0 + 0.020243075989607884*g103_0 + 0.0072892633363314694*g26_0 + 0.021195220569458977*g72_0 + -0.0031315986246608927*g101_0 + -0.01498941315137994*g74_0 + -0.0082135607648313753*g23_0 + -0.02257088878602638*g198_0 + 0.011984501560638836*g59_0 + 0.0090019465192618872*g138_0 + 0.010242690054271891*g100_0 + 0.010872853525235829*g167_0 + 0.06125269867874597*g114_0 + -0.0090130232819232055*g106_0 + 0.010716939919441412*g102_0) + (0.024172578958639276*g119_0 + -0.021541245806037116*g4_0 + -0.016025025010627254*g120_0 + -0.032900780680444996*g178_0 + -0.028137329138248585*g104_0 + 0.016991487223944363*g78_0 + -0.028470414526839204*g19_0 + -0.0023781479095068836*g76_0 + -0.061043721849128846*g33_0 + 0.0044288951365222913*g90_0 + -0.02698634074997185*g17_0 + 0.02000055426124616*g129_0 + 0.013800203138477596*g105_0 + 0.038321857246827781*g116_0 + -0.009112601974255766*g151_0 + -0.025573838785460431*g193_0 + -0.03348685124701016*g82_0 + -0.0082761703574974321*g77_0 + -0.015541379603357061*g87_0 + 0.0065509264620642492*g89_0 + 0.0046926462546438112*g68_0 + -0.0086556725047498562*g71_0); const v8d a1 = (0.1875787988003966*g_one_1 + 0.061174961720337553*g109_1 + -0.069891039938441799*g99_1 + -0.15319060491845135*g29_1 + 0.11307635299371725*g3_1 + -0.1135828560856879*g31_1 + -0.018891764382224178*g2_1 + -0.013299197818906027*g58_1 + 0.020243075989607884*g103_1 + 0.0072892633363314694*g26_1 + 0.021195220569458977*g72_1 + -0.0031315986246608927*g101_1 + -0.01498941315137994*g74_1 + -0.0082135607648313753*g23_1 + -0.02257088878602638*g198_1 + 0.011984501560638836*g59_1 + 0.0090019465192618872*g138_1 + 0.010242690054271891*g100_1 + 0.010872853525235829*g167_1 + 0.06125269867874597*g114_1 + -0.0090130232819232055*g106_1 + 0.010716939919441412*g102_1) + (0.024172578958639276*g119_1 + -0.021541245806037116*g4_1 + -0.016025025010627254*g120_1 + -0.032900780680444996*g178_1 + -0.028137329138248585*g104_1 + 0.016991487223944363*g78_1 + -0.028470414526839204*g19_1 + -0.0023781479095068836*g76_1 + -0.061043721849128846*g33_1 + 0.0044288951365222913*g90_1 + -0.02698634074997185*g17_1 + 0.02000055426124616*g129_1 + 0.013800203138477596*g105_1 + 0.038321857246827781*g116_1 + -0.009112601974255766*g151_1 + -0.025573838785460431*g193_1 + -0.03348685124701016*g82_1 + -0.0082761703574974321*g77_1 + -0.015541379603357061*g87_1 + 0.0065509264620642492*g89_1 + 0.0046926462546438112*g68_1 + -0.0086556725047498562*g71_1);
    std::memcpy(moment_arm + 1100, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1106, &a1, 5 * sizeof(double)); L[100] = a0[6]; }
  { const v8d a0 = (0.16757240070317342*g_one_0 + -0.090779215320467954*g24_0 + -0.054081714194312923*g98_0 + -0.020632156767339187*g20_0 + 0.023311070506957403*g105_0 + -0.031330278389600501*g108_0 + 0.040241479341002133*g25_0 + 0.1064087959132991*g3_0 + 0.024048110205731665*g27_0 + 0.028058042357013549*g91_0 + 0.15293352851418496*g109_0 + 0.018728240626119084*g72_0 + -0.0024304844548339415*g85_0 + -0.01820728397752425*g87_0 + -0.012202357973504257*g117_0 + -0.034354039182648614*g17_0 + 0.013275839618181981*g102_0 + 0.0056067461743624213*g67_0 + -0.013422673177720895*g30_0) + (-0.0036473412996083812*g112_0 + -0.023753680916112071*g104_0 + 0.00078828986146185721*g116_0 + -0.081702726408446058*g31_0 + 0.019500966430325371*g78_0 + 0.00087117838933586825*g69_0 + -0.063435050617913519*g5_0 + -0.030865584092692043*g110_0 + -0.0031883612186149259*g90_0 + 0.065925758163530385*g99_0 + -0.037396702980912702*g19_0 + -0.01472327337657584*g74_0 + 0.029525390459016507*g114_0 + 0.048013197148238679*g6_0 + -0.0093343791599123475*g88_0 + -0.036260830526949679*g92_0 + 0.0052614606415457748*g75_0 + 0.010583630825235271*g115_0); const v8d a1 = (0.16757240070317342*g_one_1 + -0.090779215320467954*g24_1 + -0.054081714194312923*g98_1 + -0.020632156767339187*g20_1 + 0.023311070506957403*g105_1 + -0.031330278389600501*g108_1 + 0.040241479341002133*g25_1 + 0.1064087959132991*g3_1 + 0.024048110205731665*g27_1 + 0.028058042357013549*g91_1 + 0.15293352851418496*g109_1 + 0.018728240626119084*g72_1 + -0.0024304844548339415*g85_1 + -0.01820728397752425*g87_1 + -0.012202357973504257*g117_1 + -0.034354039182648614*g17_1 + 0.013275839618181981*g102_1 + 0.0056067461743624213*g67_1 + -0.013422673177720895*g30_1) + (-0.0036473412996083812*g112_1 + -0.023753680916112071*g104_1 + 0.00078828986146185721*g116_1 + -0.081702726408446058*g31_1 + 0.019500966430325371*g78_1 + 0.00087117838933586825*g69_1 + -0.063435050617913519*g5_1 + -0.030865584092692043*g110_1 + -0.0031883612186149259*g90_1 + 0.065925758163530385*g99_1 + -0.037396702980912702*g19_1 + -0.01472327337657584*g74_1 + 0.029525390459016507*g114_1 + 0.048013197148238679*g6_1 + -0.0093343791599123475*g88_1 + -0.036260830526949679*g92_1 + 0.0052614606415457748*g75_1 + 0.010583630825235271*g115_1);
    std::memcpy(moment_arm + 1111, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1117, &a1, 5 * sizeof(double)); L[101] = a0[6]; }
  { const v8d a0 = (0.14055060749746781*g_one_0 + -0.088934695670102315*g119_0 + -0.075018993192505212*g98_0 + -0.073290534061407772*g31_0 + -0.039970108390023497*g82_0 + 0.012374991848126762*g27_0 + -0.0021784687179871791*g76_0 + 0.072916007352068463*g3_0 + -0.018524456884717096*g19_0 + -0.0089776718842765977*g87_0 + 0.0086620791191661731*g105_0 + 0.10489294877855891*g34_0 + -0.0002381083758346069*g68_0 + -0.013291268716810922*g77_0 + -0.011192057713185983*g2_0 + 0.010116176253694329*g103_0 + -0.011953151510334829*g74_0 + -0.0087096235693903713*g71_0 + -0.013238201896991814*g120_0 + -0.040332164897356693*g29_0) + (0.15794943503815245*g24_0 + -0.017280755317722798*g4_0 + 0.013775218874020658*g116_0 + 0.011496518113111519*g72_0 + -0.02845087342756393*g108_0 + 0.040513554583174065*g25_0 + -0.023377725339129626*g110_0 + 0.0080614386486937192*g102_0 + 0.12949987665618728*g113_0 + -0.0014787641934255486*g88_0 + -0.022143322377613996*g17_0 + 0.023606810990114878*g95_0 + 0.0057786184214924383*g70_0 + 0.28946296404482924*g94_0 + 0.005660202604058113*g100_0 + -0.016179056684689747*g104_0 + 0.0080458728210061111*g78_0 + 0.003914534803101893*g73_0 + 0.0080270426229216065*g16_0); const v8d a1 = (0.14055060749746781*g_one_1 + -0.088934695670102315*g119_1 + -0.075018993192505212*g98_1 + -0.073290534061407772*g31_1 + -0.039970108390023497*g82_1 + 0.012374991848126762*g27_1 + -0.0021784687179871791*g76_1 + 0.072916007352068463*g3_1 + -0.018524456884717096*g19_1 + -0.0089776718842765977*g87_1 + 0.0086620791191661731*g105_1 + 0.10489294877855891*g34_1 + -0.0002381083758346069*g68_1 + -0.013291268716810922*g77_1 + -0.011192057713185983*g2_1 + 0.010116176253694329*g103_1 + -0.011953151510334829*g74_1 + -0.0087096235693903713*g71_1 + -0.013238201896991814*g120_1 + -0.040332164897356693*g29_1) + (0.15794943503815245*g24_1 + -0.017280755317722798*g4_1 + 0.013775218874020658*g116_1 + 0.011496518113111519*g72_1 + -0.02845087342756393*g108_1 + 0.040513554583174065*g25_1 + -0.023377725339129626*g110_1 + 0.0080614386486937192*g102_1 + 0.12949987665618728*g113_1 + -0.0014787641934255486*g88_1 + -0.022143322377613996*g17_1 + 0.023606810990114878*g95_1 + 0.0057786184214924383*g70_1 + 0.28946296404482924*g94_1 + 0.005660202604058113*g100_1 + -0.016179056684689747*g104_1 + 0.0080458728210061111*g78_1 + 0.003914534803101893*g73_1 + 0.0080270426229216065*g16_1);
    std::memcpy(moment_arm + 1122, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1128, &a1, 5 * sizeof(double)); L[102] = a0[6]; }
  { const v8d a1 = (0.15282406181915248*g_one_1) + (0.018960008683066985*g1_1);
    std::memset(moment_arm + 1133, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1139, &a1, 5 * sizeof(double)); L[103] = a1[5]; }
  { const v8d a1 = (0.17649402685399199*g_one_1 + -9.1292828760720877e-05*g13_1) + (0.019223789469478305*g1_1);
    std::memset(moment_arm + 1144, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1150, &a1, 5 * sizeof(double)); L[104] = a1[5]; }
  { const v8d a1 = (0.061721761276231704*g_one_1) + (0.018351482630574806*g1_1);
    std::memset(moment_arm + 1155, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1161, &a1, 5 * sizeof(double)); L[105] = a1[5]; }
  { const v8d a1 = (0.10026081488891966*g_one_1 + -0.00074467102800991462*g13_1) + (0.019773266224851524*g1_1 + 0.00016602717006170768*g63_1);
    std::memset(moment_arm + 1166, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1172, &a1, 5 * sizeof(double)); L[106] = a1[5]; }
  { const v8d a1 = (0.14350209118044077*g_one_1 + -0.0006443574816353254*g13_1) + (0.019753416593369048*g1_1 + 0.00014204094510047516*g63_1);
    std::memset(moment_arm + 1177, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1183, &a1, 5 * sizeof(double)); L[107] = a1[5]; }
  { const v8d a1 = (0.18896735587326757*g_one_1 + -0.012190529286580161*g13_1) + (-0.0096097257372967509*g1_1 + 7.6485473083960051e-05*g269_1);
    std::memset(moment_arm + 1188, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1194, &a1, 5 * sizeof(double)); L[108] = a1[5]; }
  { const v8d a1 = (0.1803810416701824*g_one_1 + -0.011314600344683866*g13_1) + (-0.010166861825412548*g1_1 + 7.5047131347661766e-05*g269_1);
    std::memset(moment_arm + 1199, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1205, &a1, 5 * sizeof(double)); L[109] = a1[5]; }
  { const v8d a1 = (0.14528402172990038*g_one_1 + 0.0041156866190291434*g13_1 + 0.00059308492869950338*g238_1) + (-0.015504427162474892*g1_1 + -2.1624658717477171e-06*g308_1 + -0.0060724210605351461*g63_1);
    std::memset(moment_arm + 1210, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1216, &a1, 5 * sizeof(double)); L[110] = a1[5]; }
  { const v8d a1 = (0.14328771737412008*g_one_1 + -0.0097140182743692214*g13_1) + (-0.010902805651531499*g1_1 + 7.4015065198838516e-06*g306_1);
    std::memset(moment_arm + 1221, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1227, &a1, 5 * sizeof(double)); L[111] = a1[5]; }
  { const v8d a1 = (0.11051449644038795*g_one_1 + -0.01150221325610924*g1_1 + -0.00099989157906527938*g63_1) + (-0.0046714044968547705*g13_1 + 1.76958455291709e-06*g308_1);
    std::memset(moment_arm + 1232, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1238, &a1, 5 * sizeof(double)); L[112] = a1[5]; }
  { const v8d a1 = (0.097940685875691103*g_one_1 + -0.0049345842332805959*g13_1 + -0.00036343866438469271*g63_1) + (-0.011395062525422642*g1_1 + 1.6955880867365344e-06*g308_1);
    std::memset(moment_arm + 1243, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1249, &a1, 5 * sizeof(double)); L[113] = a1[5]; }
  { const v8d a1 = (0.096436003010190549*g_one_1 + -0.011170703276185913*g1_1 + -0.00067781105158588016*g63_1) + (-0.0058360171387192416*g13_1 + 1.3084469134427671e-06*g308_1);
    std::memset(moment_arm + 1254, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1260, &a1, 5 * sizeof(double)); L[114] = a1[5]; }
  { const v8d a1 = (0.33978457477225743*g_one_1 + -0.029125175610834369*g13_1 + 0.006214126539918945*g11_1 + -0.0029775943421227282*g60_1 + -2.1557843512702104e-05*g303_1) + (-0.017371547041246761*g1_1 + 0.00058107274604836303*g238_1 + 0.00011491911517209033*g234_1 + -0.00039803270462548159*g235_1 + 0.0015749078040528453*g211_1);
    std::memset(moment_arm + 1265, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1271, &a1, 5 * sizeof(double)); L[115] = a1[5]; }
  { const v8d a1 = (0.32523986160151908*g_one_1 + -0.024239567688537182*g13_1 + 0.0041493196616565909*g11_1 + -0.0008629037985071862*g235_1 + -0.0024070209268110903*g60_1 + -0.00027037771472469471*g237_1) + (-0.011011329858490817*g1_1 + 0.00045970352795520148*g238_1 + 0.00013270767037049401*g234_1 + 2.7134233239903423e-05*g301_1 + 0.0026327441230012839*g211_1);
    std::memset(moment_arm + 1276, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1282, &a1, 5 * sizeof(double)); L[116] = a1[5]; }
  { const v8d a1 = (0.3092867366395427*g_one_1 + 0.0014179185161752863*g214_1 + 0.00016428016434565481*g234_1 + 9.2415920135749985e-06*g301_1 + 0.0014033544053292889*g211_1 + -0.0016344197785877327*g1_1) + (-0.024724561422473333*g13_1 + 0.0014262657352183087*g11_1 + -0.00043969739020681804*g235_1 + -0.00061972604781332732*g210_1 + -1.7498632810254126e-05*g303_1);
    std::memset(moment_arm + 1287, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1293, &a1, 5 * sizeof(double)); L[117] = a1[5]; }
  { const v8d a1 = (0.16594576975389319*g_one_1 + -0.0017692049073774778*g60_1 + 7.1358874757167923e-05*g299_1 + -0.0035041904086500998*g13_1 + -9.6455090902688436e-05*g211_1 + -0.00041598048550946524*g264_1 + 7.1947699080646039e-06*g300_1 + -0.00083702224585892229*g12_1) + (-0.0030051743913892225*g1_1 + -2.6532189506064083e-05*g304_1 + 0.0039731038559702274*g0_1 + 9.9477039740515223e-05*g269_1 + 0.00021414621815077413*g213_1 + 0.00072800512962122976*g234_1 + 1.6613262217439387e-06*g302_1 + -9.2859600325498442e-06*g301_1);
    std::memset(moment_arm + 1298, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1304, &a1, 5 * sizeof(double)); L[118] = a1[5]; }
  { const v8d a1 = (0.090283356645272969*g_one_1 + 2.2209198593068478e-07*g307_1) + (-0.00073138878566437571*g60_1 + 0.0019028484496048776*g0_1);
    std::memset(moment_arm + 1309, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1315, &a1, 5 * sizeof(double)); L[119] = a1[5]; }
  { const v8d a1 = (0.017955686666121778*g_one_1 + 2.2154159451120803e-05*g264_1 + 0.005063677853274229*g11_1) + (0.015131385021440734*g0_1 + -3.0069698027888411e-07*g307_1 + -0.001979822239013091*g60_1);
    std::memset(moment_arm + 1320, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1326, &a1, 5 * sizeof(double)); L[120] = a1[5]; }
  { const v8d a1 = (0.020249975976631359*g_one_1 + 8.5366107587313579e-06*g299_1 + 0.00479705908246272*g11_1) + (0.011913365288006053*g0_1 + -5.5417134591667774e-07*g307_1 + -0.0017072051674125394*g60_1);
    std::memset(moment_arm + 1331, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1337, &a1, 5 * sizeof(double)); L[121] = a1[5]; }
  { const v8d a1 = (0.025521087637750527*g_one_1 + 1.3931520949913255e-07*g307_1 + -0.0012904105736931018*g60_1) + (0.0064650457388534498*g0_1 + 0.004907745671472976*g11_1);
    std::memset(moment_arm + 1342, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1348, &a1, 5 * sizeof(double)); L[122] = a1[5]; }
  { const v8d a1 = (0.027364934744990351*g_one_1 + 1.4303525468390949e-06*g307_1 + -0.0079492016489178044*g60_1 + -2.9553171966790871e-05*g299_1) + (0.0034668925638746914*g0_1 + 0.012052449676710033*g11_1 + 0.0019872135957069203*g210_1);
    std::memset(moment_arm + 1353, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1359, &a1, 5 * sizeof(double)); L[123] = a1[5]; }
  { const v8d a1 = (0.029979053642745678*g_one_1 + -4.1320641815285589e-06*g264_1) + (0.0098604213493196126*g0_1);
    std::memset(moment_arm + 1364, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1370, &a1, 5 * sizeof(double)); L[124] = a1[5]; }
  { const v8d a1 = (0.055159413124025017*g_one_1 + -0.0019618048731345388*g0_1) + (-0.0013644654229857511*g11_1);
    std::memset(moment_arm + 1375, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1381, &a1, 5 * sizeof(double)); L[125] = a1[5]; }
  { const v8d a1 = (0.052339406354759054*g_one_1 + -0.0037676250766220708*g0_1) + (-0.0014025331906435234*g11_1);
    std::memset(moment_arm + 1386, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1392, &a1, 5 * sizeof(double)); L[126] = a1[5]; }
  { const v8d a1 = (0.050566575161723741*g_one_1 + -0.001369308478210926*g11_1) + (-0.0048262625892505845*g0_1);
    std::memset(moment_arm + 1397, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1403, &a1, 5 * sizeof(double)); L[127] = a1[5]; }
  { const v8d a1 = (0.2288811253778478*g_one_1 + -0.00071616131486152844*g13_1) + (0.02145331003745176*g1_1);
    std::memset(moment_arm + 1408, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1414, &a1, 5 * sizeof(double)); L[128] = a1[5]; }
  { const v8d a1 = (0.23150687177995355*g_one_1 + -0.00070869324314726549*g13_1) + (0.021390967597154122*g1_1);
    std::memset(moment_arm + 1419, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1425, &a1, 5 * sizeof(double)); L[129] = a1[5]; }
  { const v8d a1 = (0.23637751504952137*g_one_1) + (0.019000457826535765*g1_1);
    std::memset(moment_arm + 1430, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1436, &a1, 5 * sizeof(double)); L[130] = a1[5]; }
  { const v8d a1 = (0.19661600924234077*g_one_1) + (0.018967701583948001*g1_1);
    std::memset(moment_arm + 1441, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1447, &a1, 5 * sizeof(double)); L[131] = a1[5]; }
  { const v8d a1 = (0.19254164765109824*g_one_1) + (0.018917219649256072*g1_1);
    std::memset(moment_arm + 1452, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1458, &a1, 5 * sizeof(double)); L[132] = a1[5]; }
  { const v8d a1 = (0.019334532403364808*g_one_1 + -0.00056720423619538679*g63_1) + (0.008393415405343543*g1_1);
    std::memset(moment_arm + 1463, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1469, &a1, 5 * sizeof(double)); L[133] = a1[5]; }
  { const v8d a1 = (0.018647839815843857*g_one_1 + -4.4679494094631329e-05*g238_1) + (0.0080338504244256391*g1_1);
    std::memset(moment_arm + 1474, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1480, &a1, 5 * sizeof(double)); L[134] = a1[5]; }
  { const v8d a1 = (0.021485626439849359*g_one_1 + 0.011039950073201922*g1_1) + (-1.0606771334628083e-07*g308_1 + -0.0030039812220815118*g13_1);
    std::memset(moment_arm + 1485, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1491, &a1, 5 * sizeof(double)); L[135] = a1[5]; }
  { const v8d a1 = (0.049364106290700066*g_one_1 + -5.6986767955236406e-07*g308_1) + (0.0035703944747009992*g1_1 + 0.00085029236419245039*g13_1);
    std::memset(moment_arm + 1496, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1502, &a1, 5 * sizeof(double)); L[136] = a1[5]; }
  { const v8d a1 = (0.033720657098826219*g_one_1 + 1.6973932833473808e-07*g308_1 + -0.0013289275437325669*g63_1) + (0.0027594054650353999*g1_1 + 0.0044913646634157089*g13_1);
    std::memset(moment_arm + 1507, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1513, &a1, 5 * sizeof(double)); L[137] = a1[5]; }
}

void gh_directions(const double* q, double* d) {
  const double q0 = q[0];
  const double q1 = q[1];
  const double q1_2 = q1*q1;
  const double q2 = q[2];
  const double q3 = q[3];
  const double q3_2 = q3*q3;
  const double q4 = q[4];
  const double q4_2 = q4*q4;
  const double q5 = q[5];
  const double q6 = q[6];
  const double q6_2 = q6*q6;
  const double q6_3 = q6_2*q6;
  const double q7 = q[7];
  const double q7_2 = q7*q7;
  const double q7_3 = q7_2*q7;
  const double q8 = q[8];
  const double q8_2 = q8*q8;
  const double q9 = q[9];
  const double q9_2 = q9*q9;
  const double q9_3 = q9_2*q9;
  const double m0 = q7_2;
  const double m1 = q6*q7;
  const double m2 = q8;
  const double m3 = q6_2*q7;
  const double m4 = q6*q7_2;
  const double m5 = q7_3;
  const double m6 = q6_3;
  const double m7 = q6_2;
  const double m8 = q7_2*q8;
  const double m9 = q7;
  const double m10 = q6;
  const double m11 = q7*q8;
  const double m12 = q3*q8;
  const double m13 = q3*q6*q7;
  const double m14 = q3*q7_2;
  const double m15 = q3_2*q8;
  const double m16 = q3_2*q7;
  const double m17 = q3*q5*q8;
  const double m18 = q3*q7;
  const double m19 = q6*q7*q8;
  const double m20 = q6*q8;
  const double m21 = q6_2*q8;
  const double m22 = q7*q8_2;
  const double m23 = q6*q8_2;
  const double m24 = q8_2;
  const double m25 = q9_3;
  const double m26 = q2*q3_2;
  const double m27 = q0*q4_2;
  const double m28 = q2*q3;
  const double m29 = q0*q6*q7;
  const double m30 = q2;
  const double m31 = q3_2*q6;
  const double m32 = q1*q3*q5;
  const double m33 = q3;
  const double m34 = q0*q5*q6;
  const double m35 = q1*q3*q4;
  const double m36 = q3*q5*q6;
  const double m37 = q5*q7_2;
  const double m38 = q2*q4_2;
  const double m39 = q2*q5*q6;
  const double m40 = q1*q5;
  const double m41 = q0*q6;
  const double m42 = q1*q5*q6;
  const double m43 = q4_2*q8;
  const double m44 = q1*q3_2;
  const double m45 = q1*q3*q6;
  const double m46 = q4*q6*q8;
  const double m47 = q1_2*q6;
  const double m48 = q3*q4*q8;
  const double m49 = q1*q4*q7;
  const double m50 = q5*q8;
  const double m51 = q1*q7;
  const double m52 = q3*q6*q8;
  const double m53 = q3*q6_2;
  const double m54 = q5*q6*q7;
  d[0] = 0.0; d[1] = 0.0; d[2] = 0.0;
  d[3] = 0.0; d[4] = 0.0; d[5] = 0.0;
  d[6] = 0.0; d[7] = 0.0; d[8] = 0.0;
  d[9] = 0.0; d[10] = 0.0; d[11] = 0.0;
  d[12] = 0.0; d[13] = 0.0; d[14] = 0.0;
  d[15] = 0.0; d[16] = 0.0; d[17] = 0.0;
  d[18] = 0.0; d[19] = 0.0; d[20] = 0.0;
  d[21] = 0.0; d[22] = 0.0; d[23] = 0.0;
  d[24] = 0.0; d[25] = 0.0; d[26] = 0.0;
  d[27] = 0.0; d[28] = 0.0; d[29] = 0.0;
  d[30] = 0.0; d[31] = 0.0; d[32] = 0.0;
  d[33] = 0.0; d[34] = 0.0; d[35] = 0.0;
  d[36] = 0.0; d[37] = 0.0; d[38] = 0.0;
  d[39] = 0.0; d[40] = 0.0; d[41] = 0.0;
  d[42] = 0.0; d[43] = 0.0; d[44] = 0.0;
  d[45] = 0.0; d[46] = 0.0; d[47] = 0.0;
  d[48] = 0.0; d[49] = 0.0; d[50] = 0.0;
  d[51] = 0.0; d[52] = 0.0; d[53] = 0.0;
  d[54] = 0.0; d[55] = 0.0; d[56] = 0.0;
  d[57] = 0.0; d[58] = 0.0; d[59] = 0.0;
  d[60] = 0.0; d[61] = 0.0; d[62] = 0.0;
  d[63] = 0.0; d[64] = 0.0; d[65] = 0.0;
  d[66] = 0.0; d[67] = 0.0; d[68] = 0.0;
  d[69] = 0.0; d[70] = 0.0; d[71] = 0.0;
  d[72] = 0.0; d[73] = 0.0; d[74] = 0.0;
  d[75] = 0.0; d[76] = 0.0; d[77] = 0.0;
  d[78] = 0.0; d[79] = 0.0; d[80] = 0.0;
  d[81] = 0.0; d[82] = 0.0; d[83] = 0.0;
  d[84] = 0.0; d[85] = 0.0; d[86] = 0.0;
  d[87] = 0.0; d[88] = 0.0; d[89] = 0.0;
  d[90] = 0.0; d[91] = 0.0; d[92] = 0.0;
  d[93] = 0.0; d[94] = 0.0; d[95] = 0.0;
  d[96] = 0.0; d[97] = 0.0; d[98] = 0.0;
  d[99] = 0.0; d[100] = 0.0; d[101] = 0.0;
  d[102] = 0.0; d[103] = 0.0; d[104] = 0.0;
  d[105] = 0.0; d[106] = 0.0; d[107] = 0.0;
  {
    const double x = -0.75291239911829222 - 0.14449787590703803*m0 + 0.069456388185206691*m1 + 0.024326159752944363*m2 + 0.19742304174459505*m3;
    const double y = 0.67374144685762938 - 0.29816815234546062*m0 - 0.018401825627149971*m1 - 0.025594936568055365*m2 + 0.021432624035113364*m3;
    const double z = 0.23216909931416735 - 0.070758806551353109*m0 + 0.30848512943047651*m1 + 0.070892588457303507*m2 + 0.21212305529866315*m3;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[108] = x*s; d[109] = y*s; d[110] = z*s;
  }
  {
    const double x = -0.70141658059975664 + 0.029774095203731137*m4 - 0.10792402120479232*m5 + 0.35644691200555267*m6;
    const double y = 0.684739042074761 - 0.16621405551608728*m4 - 0.19302035495328537*m5 + 0.12478351038077831*m6;
    const double z = 0.29260069540200501 + 0.17007107041926961*m4 - 0.0095162196833375144*m5 + 0.30732590601777104*m6;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[111] = x*s; d[112] = y*s; d[113] = z*s;
  }
  {
    const double x = -0.1869334374074175 - 0.058987141844969941*m0 + 0.21112431864863646*m1 + 0.17258695782111524*m5 + 0.06346711112789373*m7 - 0.090823179563258916*m3 + 0.036099448049056085*m8 - 0.75657721419072133*m9;
    const double y = 0.724279611373986 - 1.3525888399426134*m0 - 0.034408660288551322*m1 + 0.4721387296128593*m5 + 0.17066327964572814*m7 - 0.25864783076915948*m3 - 0.020128455795605339*m8 + 0.65335070456228517*m9;
    const double z = 0.51787018089357095 + 0.78870780887862069*m0 + 0.56928648979923302*m1 - 0.26314343851594579*m5 - 0.098341437429494513*m7 - 0.17381726619952367*m3 + 0.063278740766870969*m8 - 0.7450331589610768*m9;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[114] = x*s; d[115] = y*s; d[116] = z*s;
  }
  {
    const double x = -0.16429663040665154 + 0.13663330208783905*m5 + 0.15132200885730548*m10 - 0.78747452780409166*m9 + 0.14333242966561324*m1 - 0.097964439839302184*m7 + 0.043730963006231909*m8;
    const double y = 0.95162571444826605 - 0.076092275048325372*m5 + 0.04759069987048601*m10 - 0.38478935753754756*m9 - 0.17553187258285644*m1 + 0.035242942825115441*m7 - 0.016154875641721633*m8;
    const double z = 0.35546210490670638 + 0.012037701344208531*m5 + 0.35481577560138894*m10 - 0.014939900086283998*m9 + 0.29747619920449619*m1 - 0.37782235904317762*m7 + 0.064732187741213296*m8;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[117] = x*s; d[118] = y*s; d[119] = z*s;
  }
  {
    const double x = -0.12675817434654779 - 0.5935239560611657*m9 - 0.1028264107626566*m1 + 0.092231124791873176*m11 + 0.39572208273723358*m4;
    const double y = 1.1186533776542016 - 0.54982527044328633*m9 - 0.15641582045423882*m1 + 0.0014198671540071354*m11 + 0.028095855154915146*m4;
    const double z = 0.232552902222672 + 0.11949239160171608*m9 + 0.59780978721023115*m1 + 0.099271124174442574*m11 - 0.13191416887375326*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[120] = x*s; d[121] = y*s; d[122] = z*s;
  }
  {
    const double x = -0.069137264145851196 + 0.26881194057363189*m0 + 0.32967170392728079*m1 - 0.99295021352169854*m9 + 0.044800331961775547*m2;
    const double y = 0.99010661841371106 - 0.19010767353154362*m0 - 0.085994795236000537*m1 - 0.23597244634485498*m9 - 0.025402110834550698*m2;
    const double z = 0.25503907777690105 - 0.054648969840700147*m0 + 0.48110127529447055*m1 + 0.099977361878399507*m9 + 0.085523428950971619*m2;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[123] = x*s; d[124] = y*s; d[125] = z*s;
  }
  {
    const double x = -0.13507609812670265 - 0.65040273452597019*m9 + 0.16342875890801289*m1 + 0.044309239821033616*m2 + 0.18519624484285896*m4;
    const double y = 1.1322301588237493 - 0.59550341582714472*m9 - 0.014760869518960041*m1 - 0.014796904812613346*m2 - 0.053808365006569429*m4;
    const double z = 0.21032603858412446 + 0.036560213510972613*m9 + 0.75570819977881698*m1 + 0.076011508969930711*m2 - 0.19281072566219015*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[126] = x*s; d[127] = y*s; d[128] = z*s;
  }
  {
    const double x = -0.17418599530436213 - 0.58634125017988381*m9 + 0.37470263767054113*m1 + 0.04995429604614042*m2;
    const double y = 1.1578987151173799 - 0.56059282465669114*m9 - 0.087681302523542476*m1 - 0.026606208033403012*m2;
    const double z = 0.19711540967414901 + 0.0073282514599019672*m9 + 0.57477094958932917*m1 + 0.10382279216743599*m2;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[129] = x*s; d[130] = y*s; d[131] = z*s;
  }
  {
    const double x = -0.11296773998630912 - 0.65126876796387478*m9 + 0.62786523617948975*m1 + 0.091178907005173934*m11 - 0.23586072155598467*m10;
    const double y = 1.1927568381539326 - 0.61617202134779625*m9 + 0.021679747051576104*m1 + 0.040267117033975237*m11 - 0.10681176380571383*m10;
    const double z = 0.16560634041164621 + 0.074645897413006118*m9 + 0.50747695062102982*m1 + 0.072490255641938922*m11 + 0.05048365928365578*m10;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[132] = x*s; d[133] = y*s; d[134] = z*s;
  }
  {
    const double x = -0.43872325787674787 - 0.30666082113469406*m0 + 0.15104002811656086*m1 + 0.24270525915518124*m4 + 0.10918397596492369*m2;
    const double y = 0.94493087660935937 - 0.31731782424501298*m0 - 0.23360942873477658*m1 + 0.14026434860247053*m4 + 0.046455686711127972*m2;
    const double z = 0.099609168465085135 + 0.079524339778606776*m0 + 1.0054332073965966*m1 - 0.35269722463549175*m4 + 0.080505527838047028*m2;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[135] = x*s; d[136] = y*s; d[137] = z*s;
  }
  {
    const double x = -0.57461149687912927 + 0.10000269713767863*m10 - 0.32568675397209207*m0 + 0.36661528830017465*m1 + 0.13510438614904483*m11 + 0.12749130683606619*m9;
    const double y = 0.72588184500795983 - 0.051904571332446504*m10 - 0.52271523353487792*m0 + 0.013251285271436184*m1 + 0.080209710698089742*m11 + 0.46184353025271141*m9;
    const double z = 0.14773319407769853 + 0.2941249651286591*m10 + 0.072217399450104913*m0 + 0.36611800366373587*m1 + 0.082873483563472503*m11 - 0.10690105856086594*m9;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[138] = x*s; d[139] = y*s; d[140] = z*s;
  }
  {
    const double x = 0.14861965681376918 - 1.8586687173096077*m9 + 1.4703758664588513*m1 + 0.85852418357797788*m0 + 0.13925899005954781*m12 - 0.070053845550759983*m5 - 0.70155031301059811*m4 - 0.42909645510351807*m10;
    const double y = 1.3917833565254187 - 1.88400693034413*m9 + 1.4295523972967776*m1 + 1.2263075438338027*m0 + 0.1214251575990714*m12 - 0.28718189354136642*m5 - 0.79766655306669032*m4 - 0.42064076120947863*m10;
    const double z = -0.16471062762548619 + 1.9674834495202447*m9 + 0.1232680050993883*m1 - 2.5478103802788232*m0 + 0.078259478998164697*m12 + 0.87383922945107617*m5 + 0.29668606529315444*m4 - 0.043872446201861259*m10;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[141] = x*s; d[142] = y*s; d[143] = z*s;
  }
  {
    const double x = -0.41529641866954237 - 0.51077174642721301*m9 + 0.13025226769977921*m13 + 0.09815757434140325*m14 + 0.14519460626575795*m15 + 0.13770683812818665*m6 + 0.0098701257738249126*m16 + 0.0012821761900953812*m4;
    const double y = 0.9343776610207144 - 0.44861497788016191*m9 + 0.24500912846977804*m13 - 0.15858791202691841*m14 + 0.15560179263107288*m15 + 0.017033582590692615*m6 + 0.29332106156446142*m16 - 0.084472788214246516*m4;
    const double z = -0.054039509378972617 + 0.34037298398340721*m9 + 0.3906593409121521*m13 - 0.31072098834815254*m14 + 0.061286198911151508*m15 + 0.068542587492270837*m6 - 0.039642261123597519*m16 + 0.10060370663191019*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[144] = x*s; d[145] = y*s; d[146] = z*s;
  }
  {
    const double x = -0.53276310759542844 - 0.60948937934953273*m0 + 0.11630371575109807*m13 + 0.27442595208558218*m5 - 0.3984942697350764*m17 + 0.0059938420357989889*m4 + 0.12403196887050931*m7;
    const double y = 0.85364318209821011 - 0.56072300602392455*m0 + 0.45513846150296028*m13 + 0.20614385996619711*m5 - 0.39532765131187236*m17 - 0.17123241471879488*m4 - 0.02374846563423073*m7;
    const double z = 0.04511104066775791 + 0.21302310596550891*m0 + 0.019736756516564351*m13 - 0.19620875078002659*m5 - 0.20456436659629942*m17 + 0.28462367386235865*m4 + 0.095708402537019108*m7;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[147] = x*s; d[148] = y*s; d[149] = z*s;
  }
  {
    const double x = -0.38903103889256552 - 0.56842947997884574*m9 + 0.14619412239582036*m13 + 0.13113451815757171*m14 - 0.3747589664014136*m17 + 0.15180135159102767*m6 + 0.011257198894885932*m18 - 0.0095458615273526087*m4;
    const double y = 0.94178609378413591 - 0.60711689108812594*m9 + 0.26861364954086586*m13 - 0.18516316774230826*m14 - 0.38476476400055487*m17 + 0.01907723075813262*m6 + 0.4430506381265214*m18 - 0.097942325300782104*m4;
    const double z = -0.074612779527815309 + 0.35927430994686543*m9 + 0.43771956029929276*m13 - 0.30200379342886668*m14 - 0.14614616239699979*m17 + 0.073013319573375132*m6 - 0.062591373465689021*m18 + 0.09488205643691501*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[150] = x*s; d[151] = y*s; d[152] = z*s;
  }
  {
    const double x = -0.11831172530376639 - 0.68015730184923739*m9 + 0.24027116536401674*m1;
    const double y = 1.2152944953289575 - 0.65422109082263402*m9 + 0.086995486692712731*m1;
    const double z = -0.13297459079138788 - 0.021438370622703418*m9 + 0.66839343087732495*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[153] = x*s; d[154] = y*s; d[155] = z*s;
  }
  {
    const double x = -0.16582047782961704 - 0.64528219796292696*m9 + 0.19429386055358869*m1;
    const double y = 1.208678644691848 - 0.67809409702435586*m9 + 0.081080625914238688*m1;
    const double z = -0.16227336341184623 - 0.02388190069111017*m9 + 0.67281456446631793*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[156] = x*s; d[157] = y*s; d[158] = z*s;
  }
  {
    const double x = -0.12048825495115748 - 0.67573854038130243*m9 + 0.22123264543032564*m1;
    const double y = 1.215691853708412 - 0.65847034713766084*m9 + 0.086336988890416633*m1;
    const double z = -0.15259863130008597 - 0.023150815060684025*m9 + 0.67540283663323064*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[159] = x*s; d[160] = y*s; d[161] = z*s;
  }
  {
    const double x = -0.93704697135362969 + 0.019619938589584152*m1 + 0.10504703607360442*m9 - 0.098500813915559857*m4 + 0.063571140562788273*m11 - 0.080220149225812803*m19;
    const double y = -0.31467252899884135 - 0.012548932875575536*m1 - 0.21394227041287883*m9 + 0.15176019954993769*m4 - 0.026033551490746102*m11 + 0.026379299231566559*m19;
    const double z = 0.19693006305856781 + 0.18198555356235518*m1 - 0.026069097089294894*m9 - 0.22088399724716531*m4 + 0.19090115040449035*m11 - 0.2818681533349694*m19;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[162] = x*s; d[163] = y*s; d[164] = z*s;
  }
  {
    const double x = -0.79183596556141433 - 0.038267570424550007*m1;
    const double y = -0.55905399990835769 + 0.025058951052894112*m1;
    const double z = 0.24535867679999743 - 0.082456402229320672*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[165] = x*s; d[166] = y*s; d[167] = z*s;
  }
  {
    const double x = -0.79320671336343962 - 0.061873632537298204*m10;
    const double y = -0.5361271586760048 + 0.059358005788291722*m10;
    const double z = 0.28864271148717152 - 0.081026119061338261*m10;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[168] = x*s; d[169] = y*s; d[170] = z*s;
  }
  {
    const double x = -0.86630370493616038 - 0.06285899557200135*m1;
    const double y = -0.40008696884851164 + 0.058714153513865289*m1;
    const double z = 0.30115321645257059 - 0.1398908608589742*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[171] = x*s; d[172] = y*s; d[173] = z*s;
  }
  {
    const double x = -0.96075987709452615 + 0.00072472409205211132*m4 + 0.00099734359807752428*m5 + 0.0069378928221077857*m9 + 0.027492645707054595*m3 - 0.069809443180531963*m1 + 0.024881817005157354*m8 - 0.028236708080904119*m19;
    const double y = -0.10150963469743489 + 0.13148249412788715*m4 + 0.045013784545756774*m5 - 0.11694289266818601*m9 + 0.15077607371928786*m3 - 0.13022123376874556*m1 - 0.024059710110189807*m8 + 0.039861229434046908*m19;
    const double z = 0.24021517516565896 - 0.099851101035251272*m4 + 0.023795080502385848*m5 - 0.012734564042436121*m9 + 0.066121608057701509*m3 - 0.1416594958167976*m1 + 0.073342015035355521*m8 - 0.11533574579317402*m19;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[174] = x*s; d[175] = y*s; d[176] = z*s;
  }
  {
    const double x = -0.93240521529213483 - 0.061270520834565828*m3 + 0.018654178560942852*m5 + 0.061485599543933581*m2 - 0.0737784459333789*m19;
    const double y = 0.0019113092979921361 + 0.18437502977849879*m3 - 0.0062022083671405392*m5 + 0.0036777142430655827*m2 - 0.10574445648320237*m19;
    const double z = 0.37948063871361193 - 0.24489479016256951*m3 + 0.034731529807093493*m5 + 0.11478860525047517*m2 - 0.10795507832033255*m19;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[177] = x*s; d[178] = y*s; d[179] = z*s;
  }
  {
    const double x = -0.91550774964543691 + 0.16631173433281504*m9 + 0.063187848358433968*m10 - 0.11212289207848841*m1;
    const double y = -0.38497144012141227 - 0.22385582937398962*m9 + 0.014206791187061252*m10 + 0.062755360164186952*m1;
    const double z = 0.24614711695875696 - 0.00027132523690683648*m9 + 0.16368490674971242*m10 - 0.13134114874682826*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[180] = x*s; d[181] = y*s; d[182] = z*s;
  }
  {
    const double x = -0.8824909325262198 + 0.1508077366946419*m9 - 0.05886184038279528*m4 + 0.021228730017881583*m2;
    const double y = -0.38769879405294932 - 0.22196962140757043*m9 + 0.059687896876184005*m4 - 0.0027411150034923229*m2;
    const double z = 0.32956509997383981 - 0.034817798949074157*m9 - 0.030603442539595519*m4 + 0.048045254620031314*m2;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[183] = x*s; d[184] = y*s; d[185] = z*s;
  }
  {
    const double x = -0.98417129578515095 + 0.18270120953743899*m9 - 0.13204045098413336*m4 + 0.087942939846271967*m1 + 0.059187016298222282*m2 - 0.047610573545632709*m19;
    const double y = -0.16728253172656479 - 0.34526240073028391*m9 + 0.054547122521055098*m4 + 0.061404181470389049*m1 + 0.0010652852916486074*m2 - 0.051048494376782418*m19;
    const double z = 0.26965555782506395 + 0.011636537697390842*m9 - 0.31119450631384427*m4 + 0.38790967602199039*m1 + 0.16176630073298676*m2 - 0.22087346887346793*m19;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[186] = x*s; d[187] = y*s; d[188] = z*s;
  }
  {
    const double x = -0.94146686940873381 + 0.036449021669847988*m10 + 0.012029576418037025*m0 + 0.094032087077831075*m1;
    const double y = -0.14114883804444092 - 0.0068005322020078451*m10 - 0.11698366734140687*m0 - 0.0084566193773753465*m1;
    const double z = 0.32677022712117992 + 0.081923650602608353*m10 - 0.059335483739196809*m0 + 0.19987921939063602*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[189] = x*s; d[190] = y*s; d[191] = z*s;
  }
  {
    const double x = -1.0055967852629795 + 0.1269143273218496*m10 + 0.063917030534938454*m9;
    const double y = 0.047497062043228275 - 0.011141108617521078*m10 - 0.27036536577614639*m9;
    const double z = 0.25702892995773846 + 0.29004037753045747*m10 - 0.0081259371934201564*m9;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[192] = x*s; d[193] = y*s; d[194] = z*s;
  }
  {
    const double x = -0.90930275948389061 - 0.025697186292164335*m0 + 0.16273600254075196*m1;
    const double y = 0.075041684570086267 - 0.17800437851461728*m0 - 0.0072985086782192798*m1;
    const double z = 0.4264801488643587 - 0.094427570667459076*m0 + 0.30743227445317389*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[195] = x*s; d[196] = y*s; d[197] = z*s;
  }
  {
    const double x = -0.90155098878892437 + 0.061569021580330507*m10 + 0.0013503090983284219*m5 + 0.054119047893212001*m4;
    const double y = -0.2240361451902749 - 0.012725160154403874*m10 - 0.056753800714132309*m5 - 0.004757807610587461*m4;
    const double z = 0.37587934844088416 + 0.11523957707498246*m10 - 0.041377270005533685*m5 + 0.10283964220639479*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[198] = x*s; d[199] = y*s; d[200] = z*s;
  }
  {
    const double x = -0.94700909097811947 + 0.12980321101003428*m2 + 0.06656557064658658*m10 - 0.048652622739148485*m1;
    const double y = 0.018645741258444055 + 0.042156312472379665*m2 + 0.043692625125742575*m10 - 0.043767834525539583*m1;
    const double z = 0.32244861418182075 + 0.27459054733126015*m2 + 0.1415964728755095*m10 - 0.10340200097132013*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[201] = x*s; d[202] = y*s; d[203] = z*s;
  }
  {
    const double x = -0.95774410228758688 + 0.15778797869341843*m2 + 0.16171261040144891*m10 + 0.087005614188957137*m9 - 0.14985984169802219*m1;
    const double y = 0.13011777151460274 + 0.032411699590213131*m2 + 0.0030122659004947509*m10 - 0.0087970908566347532*m9 + 0.0044250240184053177*m1;
    const double z = 0.33677676099336606 + 0.23230105496556316*m2 + 0.25288653811826572*m10 + 0.13696221021158905*m9 - 0.23661333894807321*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[204] = x*s; d[205] = y*s; d[206] = z*s;
  }
  {
    const double x = -0.91669952702031621 + 0.074914777049193276*m11 - 0.030817094160118224*m1 + 0.013199092127885446*m5;
    const double y = 0.21126020906318832 + 0.15617607344543508*m11 + 0.045953138974468323*m1 + 0.031720639297329337*m5;
    const double z = 0.3516789559285593 + 0.049700110190792311*m11 - 0.14261053563210757*m1 + 0.0037830389864733334*m5;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[207] = x*s; d[208] = y*s; d[209] = z*s;
  }
  {
    const double x = -0.92885204087421958 - 0.017173572855487106*m4 + 0.079048148137922797*m8 + 0.022081312409925301*m5 + 0.046903265469540413*m20;
    const double y = 0.29471565121563492 + 0.017198795773828556*m4 + 0.10446389168305154*m8 + 0.049430768343579769*m5 + 0.17370898611470842*m20;
    const double z = 0.24056498945919574 - 0.17575190072340058*m4 + 0.071314258549434545*m8 + 0.010497511917982809*m5 - 0.077421049080197646*m20;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[210] = x*s; d[211] = y*s; d[212] = z*s;
  }
  {
    const double x = -0.81321479609942415 - 0.32030190167150846*m20 + 0.065182257019474582*m9 - 0.24047266731212047*m7 - 0.072405537601031716*m2 + 0.36247746143646553*m21 + 0.097735013710182922*m3;
    const double y = -0.019134107292182047 + 0.14395600162565303*m20 + 0.33024410601908999*m9 + 0.039175144979740582*m7 + 0.15192277969603371*m2 - 0.28636493347998532*m21 + 0.039417433993600419*m3;
    const double z = 0.67221457640705817 - 0.6969334699454065*m20 - 0.093933971739777286*m9 - 0.51155118356858753*m7 - 0.21357264077394822*m2 + 0.55062474263203509*m21 + 0.20077242127412759*m3;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[213] = x*s; d[214] = y*s; d[215] = z*s;
  }
  {
    const double x = -0.88412919152158365 - 0.052588133414421014*m10 + 0.10718176656922336*m9 - 0.033632952537800659*m2;
    const double y = 0.37204994826294369 - 0.0078005276163778253*m10 + 0.18138130346277934*m9 + 0.016412487655895827*m2;
    const double z = 0.32838092864199497 - 0.27626367357260062*m10 + 0.0047110342782931032*m9 - 0.25289147439850934*m2;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[216] = x*s; d[217] = y*s; d[218] = z*s;
  }
  {
    const double x = -0.90427167086032489 - 0.062781121520384481*m20 + 0.016990480411603701*m9 - 0.057384302127418213*m7;
    const double y = -0.096864253090115163 + 0.18255646095210465*m20 + 0.19981972311396609*m9 - 0.040881706719112988*m7;
    const double z = 0.45268928268173525 - 0.23376525968390521*m20 - 0.005829127783144589*m9 - 0.13272618507521433*m7;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[219] = x*s; d[220] = y*s; d[221] = z*s;
  }
  {
    const double x = -0.79953849197534677 - 0.041232766139784993*m22 - 0.12556754022560837*m23;
    const double y = -0.2433515209413227 + 0.32485436967557579*m22 - 0.14149263476505791*m23;
    const double z = 0.5495317202807023 + 0.045842842863676812*m22 - 0.25436253358603095*m23;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[222] = x*s; d[223] = y*s; d[224] = z*s;
  }
  {
    const double x = -0.74808041297885142 - 0.04777123552017571*m8 - 0.0073658268431028313*m7;
    const double y = -0.39483199088147641 + 0.12103353204052068*m8 - 0.088679764351583687*m7;
    const double z = 0.53334669897921916 + 0.013833569032631656*m8 - 0.083399806744731325*m7;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[225] = x*s; d[226] = y*s; d[227] = z*s;
  }
  {
    const double x = -0.74420840183991532 - 0.048793984827711287*m8 + 0.016224152323832012*m6;
    const double y = -0.43667828869189385 + 0.090656329494473331*m8 - 0.085090298708876758*m6;
    const double z = 0.50483613975364705 + 0.001114318031324808*m8 - 0.054251066504021402*m6;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[228] = x*s; d[229] = y*s; d[230] = z*s;
  }
  {
    const double x = -0.71271267623431023 + 0.039351116795943983*m7 - 0.054414445937761631*m8 - 0.066831920336669098*m23;
    const double y = -0.53739827929833262 - 0.079379655629544507*m7 + 0.087628143286151122*m8 - 0.062355514579425793*m23;
    const double z = 0.450267374338152 - 0.038630658131488665*m7 + 0.016825314722829006*m8 - 0.20347324001709066*m23;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[231] = x*s; d[232] = y*s; d[233] = z*s;
  }
  {
    const double x = -0.70510016930444364 - 0.071273568730691808*m8 - 0.11968707584994055*m21 + 0.064671176502962502*m10;
    const double y = -0.44326094378516084 + 0.14413165436228689*m8 - 0.041314951649041046*m21 - 0.11683492047932653*m10;
    const double z = 0.55255102407458534 + 0.022763049847413723*m8 - 0.20340831814031188*m21 - 0.021819106250528974*m10;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[234] = x*s; d[235] = y*s; d[236] = z*s;
  }
  {
    const double x = -0.67850335515293536 + 0.039761117114362879*m10 - 0.22463516777238698*m22 + 0.075070472770375374*m24;
    const double y = -0.53688076765210102 - 0.091900168422559977*m10 + 0.34795657870212326*m22 - 0.25282016870351498*m24;
    const double z = 0.50413254587848777 - 0.060243708055001663*m10 + 0.099186389235285971*m22 - 0.21797101409757422*m24;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[237] = x*s; d[238] = y*s; d[239] = z*s;
  }
  {
    const double x = -0.77138729134571082 - 0.074950848833303163*m11 + 0.12896603950152213*m1 - 0.18715794184857024*m23 - 0.029635766265727146*m0;
    const double y = -0.20460251013251149 + 0.068263348229825063*m11 - 0.094063912213115927*m1 + 0.070454259752490089*m23 + 0.031352327003512856*m0;
    const double z = 0.60004907714710087 - 0.077575298928593675*m11 + 0.13868043954523571*m1 - 0.2190096400529889*m23 - 0.032262542070686406*m0;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[240] = x*s; d[241] = y*s; d[242] = z*s;
  }
  {
    const double x = -0.78549153749690892 + 0.21317911666658446*m1 - 0.1182172724839306*m2 - 0.094118283936019703*m9 - 0.089693915650455452*m10;
    const double y = 0.041902755632827887 - 0.12955214756593078*m1 + 0.079036593640159913*m2 - 0.014685508884228*m9 + 0.076041987837420916*m10;
    const double z = 0.6379976125449488 + 0.37760930476561744*m1 - 0.20674242514979024*m2 - 0.17475237528425014*m9 - 0.16796140986714816*m10;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[243] = x*s; d[244] = y*s; d[245] = z*s;
  }
  {
    const double x = -0.97590312519998723 + 0.28081627083922461*m2 + 0.53956002541350279*m10 + 0.22526526432620303*m4 + 0.56538366851877309*m23 - 0.0019236683051178807*m5 - 0.65821515848246692*m1;
    const double y = -0.35384584464912633 + 0.207674558684735*m2 - 0.01626210188244108*m10 - 0.44572738526420552*m4 + 0.62269178595770203*m23 + 0.1123592926445706*m5 + 0.60091685741974632*m1;
    const double z = 0.036006192033077776 + 0.87619267802580358*m2 + 0.8444257695019346*m10 - 0.10117236554716977*m4 - 0.59536270138533087*m23 + 0.027485866800254076*m5 - 0.25629766101520463*m1;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[246] = x*s; d[247] = y*s; d[248] = z*s;
  }
  {
    const double x = -0.19043404570171865 - 0.63188031854591808*m9 - 0.27732857717902154*m1 + 0.089720576831541568*m2 + 0.39196316624156397*m7 + 0.28799827981588488*m4 - 0.002658671368505585*m25;
    const double y = 1.140863560891231 - 0.67117065009161647*m9 + 0.55766225111134116*m1 + 0.10130549135164951*m2 - 0.11087808849096252*m7 - 0.36917301907471317*m4 - 0.0010703688634787784*m25;
    const double z = 0.026523935358664045 - 0.0034525045511489185*m9 + 1.1760719764105032*m1 - 0.011003410878517049*m2 - 0.14121969479264493*m7 - 0.3306848998567844*m4 - 0.0035636829775185517*m25;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[249] = x*s; d[250] = y*s; d[251] = z*s;
  }
  {
    const double x = -0.19043404570171865 - 0.63188031854591808*m9 - 0.27732857717902154*m1 + 0.089720576831541568*m2 + 0.39196316624156397*m7 + 0.28799827981588488*m4 - 0.002658671368505585*m25;
    const double y = 1.140863560891231 - 0.67117065009161647*m9 + 0.55766225111134116*m1 + 0.10130549135164951*m2 - 0.11087808849096252*m7 - 0.36917301907471317*m4 - 0.0010703688634787784*m25;
    const double z = 0.026523935358664045 - 0.0034525045511489185*m9 + 1.1760719764105032*m1 - 0.011003410878517049*m2 - 0.14121969479264493*m7 - 0.3306848998567844*m4 - 0.0035636829775185517*m25;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[252] = x*s; d[253] = y*s; d[254] = z*s;
  }
  {
    const double x = -0.2724681631352312 - 0.60446488791707309*m9 + 0.060686225439811725*m1 + 0.17345100782021194*m4;
    const double y = 1.1476204771608536 - 0.70903992577229469*m9 + 0.098904318187935186*m1 - 0.10030084196504184*m4;
    const double z = -0.013396950694406204 + 0.015875767010772278*m9 + 1.0352669938696129*m1 - 0.33660449645348045*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[255] = x*s; d[256] = y*s; d[257] = z*s;
  }
  {
    const double x = -0.28095179154645677 - 0.60603632245710015*m9 + 0.079158147738959142*m1 + 0.15780696387218004*m4;
    const double y = 1.1493100950421093 - 0.72901909600040127*m9 + 0.1520557014513674*m1 - 0.13752116292841116*m4;
    const double z = -0.055968346953425015 + 0.013607753923460163*m9 + 1.1225821605538318*m1 - 0.37688752539881826*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[258] = x*s; d[259] = y*s; d[260] = z*s;
  }
  {
    const double x = -0.26752614596652047 - 0.61432829102371889*m9 + 0.096824920818638499*m1 + 0.15589093229122714*m4;
    const double y = 1.1544927117510166 - 0.72415350054922345*m9 + 0.12469004765403932*m1 - 0.12115237707493619*m4;
    const double z = -0.023040404731552295 + 0.012862083237594935*m9 + 1.0988554979405565*m1 - 0.36668777028610189*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[261] = x*s; d[262] = y*s; d[263] = z*s;
  }
  {
    const double x = -0.28560365442276991 - 0.6035686771855342*m9 + 0.083198430883914959*m1 + 0.15639310089819591*m4;
    const double y = 1.1489372619900555 - 0.73303918816693681*m9 + 0.14976759359675026*m1 - 0.13689009107506109*m4;
    const double z = -0.053727009736751756 + 0.012997293961854426*m9 + 1.1335223129580381*m1 - 0.38425010362230533*m4;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[264] = x*s; d[265] = y*s; d[266] = z*s;
  }
  {
    const double x = -0.87530195726707316 - 0.51750862067416104*m26 - 1.2540209297239198*m27;
    const double y = -0.50364461573234931 + 1.1868092829139076*m26 + 1.8703832678939512*m27;
    const double z = 0.068597979874693252 + 0.10999629844297755*m26 - 0.88124654219776977*m27;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[267] = x*s; d[268] = y*s; d[269] = z*s;
  }
  {
    const double x = -0.72865243806288449 - 0.04221780761067561*m18 - 0.66177295416652671*m28 - 2.2519399103925219*m27 - 0.12318596467498306*m29;
    const double y = -0.71633356129241232 + 0.07961381601729843*m18 + 0.79404278298811704*m28 + 2.1046995209945583*m27 + 0.13937142365374508*m29;
    const double z = -0.026287403711472149 - 0.031118478936230952*m18 + 0.17472263982257291*m28 - 0.52997518958963385*m27 - 0.27364675892998447*m29;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[270] = x*s; d[271] = y*s; d[272] = z*s;
  }
  {
    const double x = -0.61327187284620344 - 0.057685911579506512*m18 - 3.1068354991212654*m27 - 0.62815059500117676*m30 + 0.11487062744655195*m31;
    const double y = -0.81147489424796582 + 0.096860624939516762*m18 + 2.1762055454879792*m27 + 0.49485384576534686*m30 - 0.10141336579198691*m31;
    const double z = -0.14911173271795394 + 0.04624602125975201*m18 - 0.58620299150652755*m27 + 0.13808382456694018*m30 + 0.15179813345463394*m31;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[273] = x*s; d[274] = y*s; d[275] = z*s;
  }
  {
    const double x = 0.95740750406549002 - 0.075135825391975775*m16 - 4.7273669441072288*m32 - 1.8240076938331493*m33 + 0.53330415818366195*m34 + 7.2949379017381535*m35 - 0.26375850672156953*m30;
    const double y = -1.4123601925737621 + 0.15100049933007187*m16 - 0.60415594166941999*m32 + 0.6395170552738586*m33 - 0.34137776565000943*m34 - 1.2600847334534155*m35 + 0.082830235816966566*m30;
    const double z = -0.3185335361066754 + 0.090207197019391713*m16 + 6.777206338975402*m32 + 0.19130503687102454*m33 + 0.35417399669759619*m34 - 3.7685533114888279*m35 + 0.46359510781972063*m30;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[276] = x*s; d[277] = y*s; d[278] = z*s;
  }
  {
    const double x = 0.88340901979226238 - 0.55048733837995789*m18 + 6.2621232323983076*m32 - 1.2187919134590595*m33 - 0.36100345927053462*m36 - 0.6700433412070449*m37 - 1.1982072057192756*m38;
    const double y = -1.2302985770127874 + 0.14862222737820058*m18 - 2.0070853813189018*m32 + 0.32728620494214672*m33 + 0.17044852670424077*m36 + 0.11617791945571977*m37 - 0.45530873153173318*m38;
    const double z = -0.53577689363163328 + 0.25811693768302185*m18 + 1.130096349902558*m32 + 0.43106261487154773*m33 - 0.23048373338383535*m36 + 0.22455624952443867*m37 + 1.7624827062502766*m38;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[279] = x*s; d[280] = y*s; d[281] = z*s;
  }
  {
    const double x = 1.3699432292946052 - 0.52827740594302941*m18 - 7.5437419498738318*m32 - 1.9324911659013373*m33 + 0.38431350020916938*m39 + 9.2400324395225049*m40 - 0.58079655070224534*m37 - 0.32657129186805522*m41;
    const double y = -0.53876552638265862 + 0.17117661016444949*m18 - 20.667442279795889*m32 - 0.78907114121768973*m33 + 0.5137868365981263*m39 + 12.11869430620027*m40 + 0.2109901904558501*m37 - 0.026702182249807162*m41;
    const double z = -0.48059378968673716 + 0.15928635462911134*m18 + 1.84761281564614*m32 + 0.45647858397397056*m33 - 1.5264254834279714*m39 - 0.48305777099305736*m40 + 0.0737683089312903*m37 + 0.17107078792375702*m41;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[282] = x*s; d[283] = y*s; d[284] = z*s;
  }
  {
    const double x = -0.25303365971831832 - 0.37915771026565948*m9 + 0.13342969738458055*m7 + 0.85184804065687358*m42 + 0.30810144050096583*m43 + 0.10103114262893408*m5 - 0.97460213914677896*m44;
    const double y = -0.27709059525827517 - 0.23474755890149787*m9 - 0.037615993806830658*m7 + 1.2703294277571129*m42 + 0.258950470697626*m43 + 0.01543240187548984*m5 + 0.30620369780480283*m44;
    const double z = -0.96883923338620526 + 0.29722216840473081*m9 - 0.05483739304450453*m7 - 1.4215616424566819*m42 - 0.3479534184760773*m43 - 0.02737767954480003*m5 + 0.67145080837586946*m44;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[285] = x*s; d[286] = y*s; d[287] = z*s;
  }
  {
    const double x = -0.39484015557825947 - 0.51036435371592836*m9 - 0.44423774326306137*m45 - 0.1652175738790608*m46 + 0.19920760040585395*m0 + 0.088789679988408712*m6;
    const double y = -0.14947266528141617 - 0.15682576559133105*m9 - 0.37260180737456094*m45 - 0.17107497894637835*m46 - 0.00049419789939224735*m0 - 0.043791693150013127*m6;
    const double z = -0.92891829147000704 + 0.36324883854263024*m9 + 0.67801940269779615*m45 + 0.21662821057094211*m46 - 0.077199611810279165*m0 - 0.066329378038784775*m6;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[288] = x*s; d[289] = y*s; d[290] = z*s;
  }
  {
    const double x = -0.54240073594675975 - 0.30656510007520271*m9 - 0.31816204555459676*m47 + 0.029934331184296798*m12 + 0.06594237997690866*m5;
    const double y = -0.070822207215243682 - 0.13496571411158687*m9 - 0.67318143838592903*m47 + 0.081208770194026683*m12 - 0.0097795342636444633*m5;
    const double z = -0.86019383105073699 + 0.31070997092864028*m9 + 0.77517888976065885*m47 - 0.056837401896411198*m12 - 0.040486127231472928*m5;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[291] = x*s; d[292] = y*s; d[293] = z*s;
  }
  {
    const double x = -0.53660402596325207 - 0.3834416025704323*m9 - 0.12453459369328085*m48 + 0.13895359624257689*m0;
    const double y = -0.016777240712345504 - 0.097537449872861171*m9 - 0.25309424106678707*m48 - 0.059067697314607689*m0;
    const double z = -0.85047313398332491 + 0.30984388265244406*m9 + 0.17638499313892633*m48 - 0.062272557852579423*m0;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[294] = x*s; d[295] = y*s; d[296] = z*s;
  }
  {
    const double x = -0.7778303700705006 + 0.68172044434731294*m49 - 0.12102125977662979*m50;
    const double y = 0.18946003408411596 + 1.3849616360309576*m49 - 0.29218586670827512*m50;
    const double z = -0.60247099170488172 - 0.74604072140372035*m49 + 0.11319510586860958*m50;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[297] = x*s; d[298] = y*s; d[299] = z*s;
  }
  {
    const double x = -0.80667691528489027 - 0.17228414604992151*m51 - 0.05245567133105259*m1 + 0.10252584982396218*m52;
    const double y = 0.32111164192146457 - 0.5101047613164843*m51 + 0.0091616504170019802*m1 + 0.21084478943334459*m52;
    const double z = -0.50310096238789703 + 0.088555478138183111*m51 + 0.10365704648539846*m1 - 0.076374151032482518*m52;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[300] = x*s; d[301] = y*s; d[302] = z*s;
  }
  {
    const double x = -0.73557979943184049 - 0.099003616297181352*m0 - 0.13646856399567972*m1 + 0.084717848568530651*m12 + 0.23978326261584182*m53;
    const double y = 0.61385174021170907 - 0.20207193464539663*m0 + 0.014258415547655105*m1 + 0.14004672626695194*m12 + 0.20415980127230821*m53;
    const double z = -0.31166044559724937 - 0.024213346334256369*m0 + 0.31702456155461206*m1 + 0.0019021428247435451*m12 - 0.055012944398615565*m53;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[303] = x*s; d[304] = y*s; d[305] = z*s;
  }
  {
    const double x = -0.75529346021745725 - 0.28249485881815711*m0 + 0.36363532251690994*m31 - 0.49162291406365632*m17 + 0.46862665902990031*m54 + 0.27167884035801582*m14;
    const double y = 0.58536659622661391 - 0.46891310330244301*m0 + 0.2938676760873834*m31 - 0.67459098760196845*m17 - 0.062745895899268919*m54 + 0.44333466434003721*m14;
    const double z = -0.31559142414745123 + 0.17373902270351479*m0 - 0.04874210397325545*m31 + 0.074935503985070206*m17 - 0.77263588390541904*m54 - 0.25153213973736732*m14;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[306] = x*s; d[307] = y*s; d[308] = z*s;
  }
  d[309] = 0.0; d[310] = 0.0; d[311] = 0.0;
  d[312] = 0.0; d[313] = 0.0; d[314] = 0.0;
  d[315] = 0.0; d[316] = 0.0; d[317] = 0.0;
  d[318] = 0.0; d[319] = 0.0; d[320] = 0.0;
  d[321] = 0.0; d[322] = 0.0; d[323] = 0.0;
  d[324] = 0.0; d[325] = 0.0; d[326] = 0.0;
  d[327] = 0.0; d[328] = 0.0; d[329] = 0.0;
  d[330] = 0.0; d[331] = 0.0; d[332] = 0.0;
  d[333] = 0.0; d[334] = 0.0; d[335] = 0.0;
  d[336] = 0.0; d[337] = 0.0; d[338] = 0.0;
  d[339] = 0.0; d[340] = 0.0; d[341] = 0.0;
  d[342] = 0.0; d[343] = 0.0; d[344] = 0.0;
  d[345] = 0.0; d[346] = 0.0; d[347] = 0.0;
  d[348] = 0.0; d[349] = 0.0; d[350] = 0.0;
  d[351] = 0.0; d[352] = 0.0; d[353] = 0.0;
  d[354] = 0.0; d[355] = 0.0; d[356] = 0.0;
  d[357] = 0.0; d[358] = 0.0; d[359] = 0.0;
  d[360] = 0.0; d[361] = 0.0; d[362] = 0.0;
  d[363] = 0.0; d[364] = 0.0; d[365] = 0.0;
  d[366] = 0.0; d[367] = 0.0; d[368] = 0.0;
  d[369] = 0.0; d[370] = 0.0; d[371] = 0.0;
  d[372] = 0.0; d[373] = 0.0; d[374] = 0.0;
  d[375] = 0.0; d[376] = 0.0; d[377] = 0.0;
  d[378] = 0.0; d[379] = 0.0; d[380] = 0.0;
  d[381] = 0.0; d[382] = 0.0; d[383] = 0.0;
  d[384] = 0.0; d[385] = 0.0; d[386] = 0.0;
  d[387] = 0.0; d[388] = 0.0; d[389] = 0.0;
  d[390] = 0.0; d[391] = 0.0; d[392] = 0.0;
  d[393] = 0.0; d[394] = 0.0; d[395] = 0.0;
  d[396] = 0.0; d[397] = 0.0; d[398] = 0.0;
  d[399] = 0.0; d[400] = 0.0; d[401] = 0.0;
  d[402] = 0.0; d[403] = 0.0; d[404] = 0.0;
  d[405] = 0.0; d[406] = 0.0; d[407] = 0.0;
  d[408] = 0.0; d[409] = 0.0; d[410] = 0.0;
  d[411] = 0.0; d[412] = 0.0; d[413] = 0.0;
}

}  // namespace armrt::generated::das3
