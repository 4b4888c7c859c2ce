// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/das3.json --out cpp/generated`
// from the model file das3.json (sha256 f8340e0484f80bf8d41630bf34d37baef20a0c86192c1b271f3c506b89d1d36d).
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
  { const v8d a0 = (0.21379638932979125*g_one_0 + 0.12064598992112724*g10_0 + -0.0039399490673453844*g132_0 + 0.014389845004986889*g142_0) + (0.0078150070307210582*g208_0 + -0.063488590649261351*g9_0 + -0.042796653453329468*g183_0);
    std::memcpy(moment_arm + 11, &a0, 6 * sizeof(double)); std::memset(moment_arm + 17, 0, 5 * sizeof(double)); L[1] = a0[6]; }
  { const v8d a0 = (0.18293459668476961*g_one_0 + -0.059731132762993099*g9_0 + -0.0016391990562240684*g48_0 + 0.040823868018172817*g137_0 + -0.031320259160028889*g170_0) + (0.11089634586081297*g10_0 + 0.055021271090504524*g136_0 + -0.038373434883977195*g99_0 + -0.018505146331357997*g192_0 + 0.016378917810731992*g42_0);
    std::memcpy(moment_arm + 22, &a0, 6 * sizeof(double)); std::memset(moment_arm + 28, 0, 5 * sizeof(double)); L[2] = a0[6]; }
  { const v8d a0 = (0.17108113836941566*g_one_0 + -0.050197844091149163*g9_0 + 0.033879252610186067*g137_0 + -0.047455415018260019*g132_0 + 0.012628385867862323*g143_0) + (0.12083622626034886*g10_0 + 0.011104901651984595*g187_0 + -0.04683314838255339*g99_0 + 0.0084084347618108447*g118_0);
    std::memcpy(moment_arm + 33, &a0, 6 * sizeof(double)); std::memset(moment_arm + 39, 0, 5 * sizeof(double)); L[3] = a0[6]; }
  { const v8d a0 = (0.16174320990477942*g_one_0 + 0.045086995932888889*g9_0 + 0.20511492609515286*g160_0 + 0.014638036056985576*g143_0 + -0.26884503449245906*g48_0 + 0.019457452138488592*g137_0) + (0.12065332683695532*g10_0 + -0.0058878076201073371*g114_0 + -0.06912644867688246*g99_0 + -0.15287175019259602*g131_0 + 0.083025220658803175*g128_0 + -0.048624219867642614*g170_0);
    std::memcpy(moment_arm + 44, &a0, 6 * sizeof(double)); std::memset(moment_arm + 50, 0, 5 * sizeof(double)); L[4] = a0[6]; }
  { const v8d a0 = (0.16490802105943925*g_one_0 + -0.029009744211328705*g34_0 + 0.015228683468617795*g142_0 + 0.039203217864049095*g137_0) + (0.1279263754629717*g10_0 + 0.12375701424527387*g136_0 + 0.041141832960783088*g29_0);
    std::memcpy(moment_arm + 55, &a0, 6 * sizeof(double)); std::memset(moment_arm + 61, 0, 5 * sizeof(double)); L[5] = a0[6]; }
  { const v8d a0 = (0.17178842524568735*g_one_0 + 0.1494149875079118*g199_0 + -0.028969544529819632*g99_0 + -0.04137396302430358*g201_0 + 0.031789310521483843*g29_0 + 0.044587081413999884*g114_0 + -0.12701368795499179*g5_0) + (0.12076233059845057*g10_0 + 0.039566980363160378*g57_0 + -0.24291234977690826*g118_0 + -0.09649046910317681*g132_0 + 0.018105508138956661*g171_0 + 0.36524806061203741*g33_0);
    std::memcpy(moment_arm + 66, &a0, 6 * sizeof(double)); std::memset(moment_arm + 72, 0, 5 * sizeof(double)); L[6] = a0[6]; }
  { const v8d a0 = (0.15614502337434827*g_one_0 + 0.0094408177858511712*g154_0 + -0.082465168988130083*g183_0 + -0.07802488657220312*g6_0 + -0.064634848011231871*g200_0 + -0.10823294190694197*g187_0 + 0.065779182399365727*g207_0) + (0.098964330422012678*g10_0 + 0.08576962870910039*g40_0 + -0.034177835430486934*g202_0 + 0.043211051814588251*g9_0 + 0.075960514060908341*g57_0 + -0.044599864004499785*g141_0 + 0.0085760483757760415*g120_0);
    std::memcpy(moment_arm + 77, &a0, 6 * sizeof(double)); std::memset(moment_arm + 83, 0, 5 * sizeof(double)); L[7] = a0[6]; }
  { const v8d a0 = (0.16051097055086244*g_one_0 + 0.069353825315151121*g194_0 + -0.11704427969175064*g6_0 + 0.20238666610418451*g40_0 + 0.058001342692012986*g9_0 + 0.091941053995583583*g208_0 + 0.15652786491214196*g132_0 + -0.03148795561900939*g114_0 + 0.012033751491067482*g207_0) + (0.023098742006691986*g154_0 + 0.035936485015033777*g160_0 + -0.11613674452135002*g188_0 + -0.070646318150728138*g55_0 + 0.20624831301111493*g56_0 + 0.01742564484579456*g118_0 + 0.1249603785372396*g187_0 + 0.015848806076279077*g143_0);
    std::memcpy(moment_arm + 88, &a0, 6 * sizeof(double)); std::memset(moment_arm + 94, 0, 5 * sizeof(double)); L[8] = a0[6]; }
  { const v8d a0 = (0.1814648372685557*g_one_0 + 0.15275751857301809*g57_0 + 0.083818783543858633*g9_0 + -0.079595213985401508*g200_0 + 0.20991003598957669*g56_0 + 0.098510427572859161*g136_0) + (-0.0096870798572754376*g47_0 + -0.093207045123207974*g6_0 + 0.045498828225683415*g187_0 + -0.0027501706541996256*g173_0 + -0.15085261001457448*g188_0 + 0.12291562479613288*g207_0);
    std::memcpy(moment_arm + 99, &a0, 6 * sizeof(double)); std::memset(moment_arm + 105, 0, 5 * sizeof(double)); L[9] = a0[6]; }
  { const v8d a0 = (0.22997019590113618*g_one_0 + 0.016726279108780641*g57_0 + 0.011060898435236135*g171_0 + 0.013447221977497162*g201_0 + 0.0077326508222148975*g188_0 + -0.036425611880191361*g119_0 + 0.089169675547331656*g99_0 + -0.15014023831847031*g113_0 + 0.088784715833056541*g10_0 + 0.038245957475780031*g59_0) + (-0.0091653492045755385*g47_0 + 0.055767935402062277*g98_0 + 0.11973853525037093*g28_0 + 0.081712767724064481*g170_0 + 0.049641376296838138*g49_0 + 0.088087283944449465*g9_0 + -0.050091845294455234*g58_0 + 0.0028792117941211794*g136_0 + -0.068596093885086931*g8_0 + 0.14431837163689162*g29_0);
    std::memcpy(moment_arm + 110, &a0, 6 * sizeof(double)); std::memset(moment_arm + 116, 0, 5 * sizeof(double)); L[10] = a0[6]; }
  { const v8d a0 = (0.19892475404730081*g_one_0 + -1.4832154370539981*g298_0 + -0.79640730954167904*g263_0 + 1.0176520481842266*g233_0 + 0.0032290537214482644*g260_0) + (0.82373241268142916*g58_0 + -4.4460165178601923*g297_0 + -5.0972697315704689*g262_0 + 1.9420565336903928*g208_0 + 0.72268846858230595*g209_0);
    std::memcpy(moment_arm + 121, &a0, 6 * sizeof(double)); std::memset(moment_arm + 127, 0, 5 * sizeof(double)); L[11] = a0[6]; }
  { const v8d a0 = (0.19150832079079014*g_one_0 + 0.9373156358455178*g209_0 + -0.958807817689456*g261_0 + -9.8491388785351539*g297_0 + -1.5598775142826036*g296_0 + -1.1372357526526498*g263_0 + 0.0087776105248512561*g42_0) + (0.45920791231534119*g58_0 + -12.934237738490724*g262_0 + -2.4629293139413329*g298_0 + -0.0081404387184613146*g8_0 + -0.014693924892157491*g173_0 + -5.1680400523381333*g232_0 + 1.4232548505098799*g233_0);
    std::memcpy(moment_arm + 132, &a0, 6 * sizeof(double)); std::memset(moment_arm + 138, 0, 5 * sizeof(double)); L[12] = a0[6]; }
  { const v8d a0 = (0.20123337058413773*g_one_0 + -0.20102243979712964*g137_0 + -0.10859142792490686*g9_0 + 0.28285977067756207*g41_0 + 0.12342759065263462*g6_0 + -0.039857991991203649*g170_0 + 0.015791094228574973*g153_0) + (0.026348275291161183*g47_0 + 0.081315093662687785*g114_0 + 0.020411192561469928*g186_0 + -0.13542297235025302*g7_0 + -0.010417894253930386*g8_0 + 0.13886247189070383*g35_0);
    std::memcpy(moment_arm + 143, &a0, 6 * sizeof(double)); std::memset(moment_arm + 149, 0, 5 * sizeof(double)); L[13] = a0[6]; }
  { const v8d a0 = (0.10507753656545252*g_one_0 + -0.16786563338481969*g137_0 + -0.063687689210820228*g171_0 + -0.097393249971795298*g170_0 + 0.30439216003332015*g41_0 + 0.078171657151690124*g119_0 + 0.023696207543478301*g49_0 + -0.055168583635455862*g8_0) + (0.097881225040756054*g47_0 + -0.10476984307515279*g205_0 + -0.055603498561694116*g183_0 + -0.011221086328301742*g118_0 + 0.058029242980708204*g35_0 + -0.080881788360787688*g9_0 + -0.12827865602273741*g55_0);
    std::memcpy(moment_arm + 154, &a0, 6 * sizeof(double)); std::memset(moment_arm + 160, 0, 5 * sizeof(double)); L[14] = a0[6]; }
  { const v8d a0 = (0.11863663901843663*g_one_0 + 0.0068309736561840088*g109_0 + 0.0090353120722435048*g170_0 + 0.015987719255617372*g46_0 + 0.010193393384586158*g132_0 + 0.06820004976179421*g9_0 + -0.029619142960412303*g7_0 + 0.028713369131036226*g114_0 + -0.015138843859451924*g188_0) + (-0.049170322135602178*g58_0 + -0.031425602007075705*g118_0 + -0.023980336409763481*g209_0 + -0.059473980593860852*g208_0 + 0.07117502202986857*g200_0 + -0.027434071529407279*g10_0 + 0.072321282922054725*g33_0 + -0.022704307844409435*g201_0 + 0.030659695391550886*g98_0);
    std::memcpy(moment_arm + 165, &a0, 6 * sizeof(double)); std::memset(moment_arm + 171, 0, 5 * sizeof(double)); L[15] = a0[6]; }
  { const v8d a0 = (0.10891865504685884*g_one_0 + 0.11260477439907911*g33_0 + 0.014093137518497292*g192_0 + 0.082239906384849765*g188_0 + -0.12396650280104698*g56_0 + -0.061330311109780093*g199_0 + 0.021537025832189985*g169_0 + 0.010551061036897673*g140_0 + 0.022795687137870349*g200_0 + 0.013627921205011207*g34_0 + -0.0061867498793988594*g40_0) + (0.1142055527861098*g9_0 + -0.0336176651204654*g205_0 + -0.039217570324710439*g160_0 + -0.037554919116053159*g6_0 + -0.016899341398922605*g135_0 + -0.034180315706473521*g113_0 + -0.015680437745752243*g165_0 + -0.032027532629672666*g187_0 + -0.066076692002577223*g118_0 + 0.011782572050757148*g170_0);
    std::memcpy(moment_arm + 176, &a0, 6 * sizeof(double)); std::memset(moment_arm + 182, 0, 5 * sizeof(double)); L[16] = a0[6]; }
  { const v8d a0 = (0.085445025142081493*g_one_0 + 0.085040918772566101*g33_0 + -0.035890508017008924*g194_0 + -0.041215739585187428*g160_0 + 0.10561406081913825*g200_0 + -0.042148414770895301*g10_0 + 0.018731293943011925*g46_0) + (0.14782775511963053*g9_0 + -0.0066841609027046001*g205_0 + -0.0076289621868208856*g158_0 + -0.028524510559050052*g188_0 + 0.0016060707744267775*g40_0 + 0.034405803753704632*g114_0);
    std::memcpy(moment_arm + 187, &a0, 6 * sizeof(double)); std::memset(moment_arm + 193, 0, 5 * sizeof(double)); L[17] = a0[6]; }
  { const v8d a0 = (0.10155260199017856*g_one_0 + 0.057126466504868904*g33_0 + 0.014489304444940104*g186_0 + -0.059980981583356713*g160_0 + -0.076970423374514277*g208_0 + 0.036896597693293287*g170_0 + 0.062575097147943418*g59_0) + (0.14650096957019659*g9_0 + 0.0079934236473572819*g205_0 + 0.0061048046074261867*g8_0 + -0.022784281760536085*g56_0 + 0.011636169470080029*g167_0 + -0.015992425008692638*g6_0 + 0.018439905852401781*g5_0);
    std::memcpy(moment_arm + 198, &a0, 6 * sizeof(double)); std::memset(moment_arm + 204, 0, 5 * sizeof(double)); L[18] = a0[6]; }
  { const v8d a0 = (0.13850160782782681*g_one_0 + 0.022569130445614857*g137_0 + 0.098617066532576597*g47_0 + -0.026528978511330004*g173_0 + 0.15016383463179664*g154_0 + -0.039414049204997643*g195_0 + -0.122913903803248*g132_0 + 0.027671277208626763*g120_0 + -0.095879521264591316*g99_0 + -0.015240128146607228*g140_0 + -0.048638506831427716*g136_0) + (-0.098116730216774514*g199_0 + 0.095420517898610654*g10_0 + -0.010302837873367641*g153_0 + 0.063112455052402386*g6_0 + 0.040417317415288624*g206_0 + -0.014784018653153786*g118_0 + 0.045463469343995574*g8_0 + -0.049386065223551913*g170_0 + -0.054306726954662134*g9_0 + -0.042961094164920256*g187_0);
    std::memcpy(moment_arm + 209, &a0, 6 * sizeof(double)); std::memset(moment_arm + 215, 0, 5 * sizeof(double)); L[19] = a0[6]; }
  { const v8d a0 = (0.13543436128433203*g_one_0 + 0.011293667097320728*g41_0 + -0.083815565587430405*g118_0 + 0.0025276924851304009*g186_0 + -0.25983625551696593*g55_0 + 0.0061462349317180694*g193_0 + -0.10011960952576011*g205_0 + -0.17009823777884756*g99_0 + 0.09033670796539596*g8_0 + 0.049266083330776145*g47_0) + (-0.14890400368634499*g183_0 + 0.13762487796013972*g199_0 + -0.25441922487198004*g29_0 + -0.011590680781328964*g171_0 + 0.066190114527948749*g114_0 + 0.072698779099935412*g158_0 + 0.14987565331530106*g58_0 + 0.058383075080690836*g198_0 + 0.029812362088243755*g35_0);
    std::memcpy(moment_arm + 220, &a0, 6 * sizeof(double)); std::memset(moment_arm + 226, 0, 5 * sizeof(double)); L[20] = a0[6]; }
  { const v8d a0 = (0.11818465275380287*g_one_0 + 0.26702709225792759*g41_0 + -0.15074130591191351*g186_0 + -0.17154588679145416*g137_0 + -0.007876496911132725*g200_0 + -0.0048362186515223523*g208_0 + 0.16411999983114231*g56_0 + -0.088464693303833372*g118_0 + 0.01451853870383003*g193_0 + -0.1277151404886353*g205_0) + (0.18227086382931246*g183_0 + -0.0054743723133217608*g199_0 + 0.062466218851234726*g7_0 + 0.059779041980324951*g119_0 + -0.13931195317758616*g188_0 + 0.14359318832896337*g6_0 + 0.089689843459272889*g58_0 + -0.16752781549182885*g182_0 + 0.11786885394457811*g114_0 + -0.0523884597357267*g48_0);
    std::memcpy(moment_arm + 231, &a0, 6 * sizeof(double)); std::memset(moment_arm + 237, 0, 5 * sizeof(double)); L[21] = a0[6]; }
  { const v8d a0 = (0.10088639146948085*g_one_0 + 0.20789288478585927*g41_0 + -0.05687517080418316*g118_0 + -0.2511975308012509*g205_0 + 0.030236753353195433*g158_0 + 0.055517008513148426*g7_0 + 0.16798176713309673*g200_0 + -0.070111175680489343*g59_0) + (-0.22248603035203127*g55_0 + -0.017282186179597609*g154_0 + -0.021341526730955372*g201_0 + -0.00097640021551721073*g209_0 + -0.11213567157646993*g137_0 + 0.097545249114334459*g6_0 + -0.063884730463396253*g98_0 + 0.015087328693839863*g8_0);
    std::memcpy(moment_arm + 242, &a0, 6 * sizeof(double)); std::memset(moment_arm + 248, 0, 5 * sizeof(double)); L[22] = a0[6]; }
  { const v8d a0 = (0.11981197040657809*g_one_0 + 0.062880380223641036*g41_0 + -0.0049421087037176611*g201_0 + -0.024473552939324399*g137_0 + 0.02376552029970156*g172_0 + 0.020300257683421554*g48_0 + -0.042615158163879327*g199_0 + -0.071511042578635109*g118_0 + 0.013583148627307159*g209_0 + -0.019668667314577223*g195_0 + 0.1714238577830231*g6_0 + 5.3820959279075807e-05*g202_0 + -0.10194673613125153*g98_0) + (-0.14802369164154031*g55_0 + 0.030861588850173746*g204_0 + 0.026425993773272892*g7_0 + 0.008031858066987925*g136_0 + 0.16171267278216614*g200_0 + 0.0018809960391427696*g159_0 + -0.073266956597841826*g34_0 + -0.17396229927498638*g205_0 + 0.018948755215026491*g164_0 + -0.038109766183718509*g113_0 + 0.059883982042805942*g10_0 + 0.073386541825214702*g8_0);
    std::memcpy(moment_arm + 253, &a0, 6 * sizeof(double)); std::memset(moment_arm + 259, 0, 5 * sizeof(double)); L[23] = a0[6]; }
  { const v8d a0 = (0.12053637336162021*g_one_0 + -0.15801802773887527*g8_0 + 0.21534573631087653*g132_0 + 0.049901898423849934*g173_0 + -0.14546749307443704*g6_0 + 0.071541378834269601*g171_0 + -0.11160907554688659*g182_0 + 0.1858986748601146*g141_0 + 0.01539247339720253*g198_0 + 0.087615272725875867*g200_0 + -0.021674970565319421*g188_0 + 0.21737284509896823*g98_0) + (-0.044844822932368307*g55_0 + -0.067015053593814738*g158_0 + 0.12305761077496954*g194_0 + 0.093325683270520182*g28_0 + 0.034462842543442625*g206_0 + -0.050322023205510706*g54_0 + 0.1044010920989716*g160_0 + -0.046407128441009915*g5_0 + -0.12827907842620129*g10_0 + -0.082441043458314961*g57_0 + 0.052167930360817252*g143_0 + 0.013991329317158128*g165_0);
    std::memcpy(moment_arm + 264, &a0, 6 * sizeof(double)); std::memset(moment_arm + 270, 0, 5 * sizeof(double)); L[24] = a0[6]; }
  { const v8d a0 = (0.12963783685272484*g_one_0 + -0.15788943175936249*g8_0 + 0.017515981691248725*g204_0 + 0.22287861943601436*g171_0 + -0.10199614325596479*g39_0 + 0.032627814119004284*g140_0 + 0.099767948605993098*g170_0 + -0.091410509245971036*g128_0 + -0.054693503051168033*g33_0 + -0.023621547869858654*g131_0 + 0.052239371498180309*g207_0) + (-0.38923792171360855*g187_0 + 0.20464201262293361*g153_0 + -0.13490282135668746*g6_0 + -0.19773970332893856*g56_0 + 0.38608691471480028*g55_0 + 0.025177667421994142*g99_0 + 0.047703346550544805*g58_0 + 0.079360446630418843*g132_0 + 0.17748995856451472*g183_0 + 0.066025746848681344*g165_0 + 0.054482379886998535*g194_0);
    std::memcpy(moment_arm + 275, &a0, 6 * sizeof(double)); std::memset(moment_arm + 281, 0, 5 * sizeof(double)); L[25] = a0[6]; }
  { const v8d a0 = (0.14281904726340264*g_one_0 + -0.16634649777787849*g8_0 + 0.016964623945858542*g182_0 + 0.079153650797915462*g141_0 + 0.089847426781756834*g173_0 + 0.43801453117116274*g55_0 + 0.12635553230700952*g193_0 + -0.21080217653745895*g56_0 + 0.23980088988076539*g183_0 + 0.041558069972862779*g58_0 + 0.0205240387203608*g201_0 + 0.17142778513872306*g99_0 + 0.0638102389813332*g165_0) + (-0.45144578347750164*g187_0 + 0.021586772744426202*g198_0 + 0.014968191632071162*g42_0 + 0.054334301936396538*g194_0 + 0.0057152872760701488*g140_0 + -0.06646978961659801*g33_0 + -0.12888541824056321*g40_0 + 0.23277824824872737*g171_0 + -0.021006324679997537*g34_0 + 0.21245634720401113*g29_0 + -0.12527544182960088*g50_0 + -0.076788476287243182*g46_0);
    std::memcpy(moment_arm + 286, &a0, 6 * sizeof(double)); std::memset(moment_arm + 292, 0, 5 * sizeof(double)); L[26] = a0[6]; }
  { const v8d a0 = (0.1292182721039932*g_one_0 + -0.033062143397423679*g42_0 + 0.095258169187824371*g202_0 + 0.074666409373017509*g141_0 + -0.19820946577637566*g40_0 + -0.10948404247460497*g169_0 + -0.0288329311467793*g201_0 + -0.098641623233179529*g118_0 + -0.0096089306277849958*g173_0 + -0.057205745912167386*g6_0 + -0.11824678758214355*g49_0 + 0.089030445529232824*g167_0) + (-0.3523538131173356*g187_0 + 0.11546087531073952*g54_0 + -0.13115886290896078*g8_0 + -0.0076483137007145041*g194_0 + -0.18834319668214664*g56_0 + 0.15239143162243332*g183_0 + -0.035165254070645725*g132_0 + -0.099702671959023492*g186_0 + 0.06116635439688891*g182_0 + 0.12424356333846288*g171_0 + 0.35396317937049399*g55_0);
    std::memcpy(moment_arm + 297, &a0, 6 * sizeof(double)); std::memset(moment_arm + 303, 0, 5 * sizeof(double)); L[27] = a0[6]; }
  { const v8d a0 = (0.11660500616669828*g_one_0 + -0.16666461939193022*g40_0 + 0.088332791837065647*g167_0 + -0.23617854984209979*g56_0 + 0.12110233129963101*g178_0 + 0.39078044989698535*g55_0 + 0.12757007533126652*g171_0 + 0.069094589615924129*g94_0 + 0.10885426190762794*g141_0 + 0.13419645041350919*g58_0 + -0.045984795165129856*g206_0 + -0.057072429372373806*g33_0) + (-0.46770345468338675*g187_0 + 0.084901415276379927*g54_0 + -0.1043434200614549*g8_0 + 0.0082084666516363518*g137_0 + -0.07110119421981452*g84_0 + 0.13278955222909267*g208_0 + -0.054046086232020944*g34_0 + -0.16261605286145625*g49_0 + 0.097106093357081341*g150_0 + 0.078737185233110643*g154_0 + 0.13755026600172029*g183_0);
    std::memcpy(moment_arm + 308, &a0, 6 * sizeof(double)); std::memset(moment_arm + 314, 0, 5 * sizeof(double)); L[28] = a0[6]; }
  { const v8d a0 = (0.090862002380196108*g_one_0 + -0.2334947737331651*g49_0 + -0.072397614334095847*g169_0 + 0.09074530253453518*g165_0 + -0.048633141458848193*g136_0 + 0.015825042882393996*g209_0 + 0.098646913600232922*g172_0 + -0.012220892736444921*g195_0 + 0.044290339006310561*g193_0 + 0.21115175162338598*g194_0 + 0.086624578778366892*g207_0 + 0.10745413987485584*g46_0 + 0.07326954631332501*g59_0) + (-0.28489903245402215*g56_0 + 0.24014511342982431*g182_0 + 0.18328328903189908*g166_0 + -0.023565488975506248*g9_0 + -0.067180578562752322*g5_0 + -0.23966910147364212*g206_0 + 0.075622661660210325*g55_0 + 0.32283774145151295*g153_0 + -0.053511152659644352*g205_0 + 0.011538578554840638*g41_0 + -0.093776988320879176*g204_0 + -0.01850298783536531*g42_0);
    std::memcpy(moment_arm + 319, &a0, 6 * sizeof(double)); std::memset(moment_arm + 325, 0, 5 * sizeof(double)); L[29] = a0[6]; }
  { const v8d a0 = (0.062582521448262762*g_one_0 + -0.072393715649933646*g118_0 + -0.022449178451274615*g201_0 + -0.044663130760141896*g170_0 + -0.099421554581448163*g159_0 + 0.041758541339845696*g207_0 + -0.02201874300957438*g209_0 + 0.010595933335233851*g6_0 + 0.029666717549546275*g8_0 + 0.016216383554596311*g137_0 + 0.045986388756536732*g50_0) + (-0.27587484234322246*g56_0 + -0.049459796508322253*g9_0 + -0.17259157085493523*g205_0 + -0.12085564439325536*g187_0 + -0.16104366783054372*g206_0 + 0.0089552682674864468*g202_0 + 0.0048210143128992562*g84_0 + 0.021560739048868557*g28_0 + 0.13188767522404257*g194_0 + -0.1038827647871897*g49_0);
    std::memcpy(moment_arm + 330, &a0, 6 * sizeof(double)); std::memset(moment_arm + 336, 0, 5 * sizeof(double)); L[30] = a0[6]; }
  { const v8d a0 = (0.024658115067181303*g_one_0 + 0.020672361007919488*g113_0 + 0.31357546314311951*g188_0 + 0.1592774069464255*g165_0 + -0.19585888193957296*g170_0 + 0.057221107873078575*g41_0 + -0.00099489870833689145*g39_0 + 0.013892498522631145*g6_0 + -0.0095362917287441264*g209_0 + -0.013204309304050674*g99_0) + (-0.3715272589520725*g56_0 + 0.082374130136913332*g120_0 + -0.062018792748631944*g167_0 + 0.018871918205415807*g143_0 + -0.016342612434448706*g171_0 + 0.15460109358595711*g154_0 + -0.026106143434302731*g9_0 + -0.059070038716604052*g137_0 + -0.009177449414299042*g5_0);
    std::memcpy(moment_arm + 341, &a0, 6 * sizeof(double)); std::memset(moment_arm + 347, 0, 5 * sizeof(double)); L[31] = a0[6]; }
  { const v8d a0 = (0.014855672882192668*g_one_0 + 0.0121221461775948*g154_0 + -0.017107484662333146*g140_0 + 0.024714818353972073*g205_0 + -0.1434174955127705*g166_0 + 0.21022918971551183*g188_0 + 0.052364504759068405*g201_0 + 0.032589747679592065*g169_0 + 0.028110279915251869*g137_0) + (-0.29316114947258765*g56_0 + 0.054027647029972842*g120_0 + 0.050802009934370021*g207_0 + 0.074027734742226126*g50_0 + -0.013297712020510334*g109_0 + -0.041237578200761953*g99_0 + -0.029268285832375632*g131_0 + -0.1046310988447339*g47_0);
    std::memcpy(moment_arm + 352, &a0, 6 * sizeof(double)); std::memset(moment_arm + 358, 0, 5 * sizeof(double)); L[32] = a0[6]; }
  { const v8d a0 = (0.0081580187578270333*g_one_0 + -0.13877878212371467*g187_0 + 0.12405986982906268*g201_0 + -0.0066796697629030108*g48_0 + -0.1906694096128996*g47_0 + 0.10254208954941674*g29_0 + 0.034784216387231053*g120_0 + -0.071433484434058864*g28_0 + -0.034009469782583839*g195_0 + 0.20358157314460126*g131_0 + 0.0098582322154414821*g5_0 + -0.19564523604913392*g169_0 + 0.12741937821147345*g193_0) + (0.19163883599066742*g200_0 + -0.026055845459954183*g182_0 + -0.0063516862274476983*g207_0 + 0.22197493453824552*g164_0 + -0.1592751575924039*g56_0 + -0.035818107859030356*g202_0 + -0.15569732413733037*g58_0 + -0.15484955646923154*g132_0 + -0.040758254252885463*g154_0 + 0.0010798259333231154*g8_0 + 0.036394756655405522*g39_0 + -0.029909973745215916*g209_0 + -0.12000866952599951*g199_0);
    std::memcpy(moment_arm + 363, &a0, 6 * sizeof(double)); std::memset(moment_arm + 369, 0, 5 * sizeof(double)); L[33] = a0[6]; }
  { const v8d a0 = (0.023923014612517276*g_one_0 + -0.08977846517041288*g187_0 + -0.3539882792097111*g47_0 + 0.036378530244569239*g186_0 + 0.0028332769425202619*g99_0 + -0.027022829326274565*g194_0 + 0.025337543556068993*g120_0 + -0.16803557761923163*g154_0 + 0.17068199677768001*g159_0 + 0.015895002529578529*g49_0 + -0.067232645329922264*g41_0 + 0.035441081775888547*g169_0 + 0.069308786994196542*g137_0 + 0.017002261387245567*g183_0) + (-0.059893278458670089*g200_0 + 0.042639638328213755*g5_0 + 0.088227645690462694*g201_0 + 0.011372955290622705*g173_0 + -0.092199149447063644*g56_0 + 0.0045314115353961969*g165_0 + 0.066355541467303936*g207_0 + 0.076141344697648994*g29_0 + 0.068913568757463864*g50_0 + 0.039085116771111386*g59_0 + -0.10867556580092194*g166_0 + -0.002619210672138265*g140_0 + -0.097233849201844719*g208_0 + -0.019217161232023123*g57_0);
    std::memcpy(moment_arm + 374, &a0, 6 * sizeof(double)); std::memset(moment_arm + 380, 0, 5 * sizeof(double)); L[34] = a0[6]; }
  { const v8d a0 = (0.086144246477443315*g_one_0 + 0.22225880968788964*g150_0 + -0.0076138958007954368*g173_0 + -0.0089227763489449202*g178_0 + -0.37303434664197793*g153_0 + -0.1097076135683073*g188_0 + -0.079129186665345838*g99_0 + -0.099429852530380364*g166_0 + 0.079769280494004322*g207_0 + 0.087372087874888732*g50_0 + 0.070751326789645769*g170_0 + 0.039276621952580609*g114_0 + 0.057185911296629414*g200_0) + (-0.090809981140989218*g199_0 + -0.14890238733497557*g7_0 + -0.12888107601538223*g205_0 + -0.002308537034700687*g143_0 + -0.1243985847393224*g58_0 + -0.27045879201259243*g47_0 + -0.06497985779333762*g33_0 + 0.072096351519530269*g118_0 + -0.0061814176272841784*g8_0 + 0.062199426211129824*g5_0 + 0.13151190070873486*g183_0 + 0.11052588513846101*g35_0 + -0.16171988998404077*g208_0);
    std::memcpy(moment_arm + 385, &a0, 6 * sizeof(double)); std::memset(moment_arm + 391, 0, 5 * sizeof(double)); L[35] = a0[6]; }
  { const v8d a1 = (0.17458338744227*g_one_1 + -0.10770318217503758*g258_1 + 0.30986650239129165*g17_1 + 0.074989927604106207*g274_1 + -0.0016886970607243729*g16_1 + 0.017291986853230915*g4_1 + 0.0025173069488126404*g283_1 + 0.053284751439595948*g227_1 + 0.05882344749412808*g294_1 + -0.69536966099462127*g69_1 + -0.012366187158333418*g280_1 + -0.010532823152192838*g20_1 + -0.10875886120539222*g253_1) + (-0.013612631431100036*g19_1 + -0.018308499526657113*g3_1 + 0.04072768405181932*g229_1 + -0.0012061220994630767*g248_1 + -0.0051802638780183438*g225_1 + 0.0057634870971738587*g2_1 + -0.0046275337500204334*g18_1 + 0.035020294885006784*g224_1 + 0.0018192178169480953*g74_1 + -0.37583306142076545*g244_1 + 0.049126848994484447*g285_1 + 0.73144530186182344*g220_1);
    std::memset(moment_arm + 396, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 402, &a1, 5 * sizeof(double)); L[36] = a1[5]; }
  { const v8d a1 = (0.1507025905841724*g_one_1 + 0.017123444962302441*g3_1 + 0.024699196771042903*g19_1 + -0.0014441368223903799*g280_1 + 9.943370209169062e-05*g16_1 + 0.024314437533536147*g289_1 + 0.0020405820205962656*g74_1 + -0.019617503404749378*g257_1 + 0.0027117427208195304*g4_1 + 0.0046206182840753977*g276_1) + (0.0057205130014667763*g274_1 + -0.011187372705750149*g244_1 + -0.011632073697313179*g229_1 + 0.015079306660234132*g293_1 + -0.0018945606045842405*g223_1 + -0.01849302371337035*g292_1 + 0.0044540427148652435*g2_1 + -0.0088701476198979924*g285_1 + -0.0054218046619229571*g221_1);
    std::memset(moment_arm + 407, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 413, &a1, 5 * sizeof(double)); L[37] = a1[5]; }
  { const v8d a1 = (0.13445555705308682*g_one_1 + 0.0091928726283628474*g220_1 + 0.031338346402532941*g19_1 + -0.0081441010048608053*g244_1 + 0.0050903379498349706*g2_1 + 0.00195152991834839*g20_1 + 0.0059676209219822933*g229_1 + 0.00041758639809604285*g272_1 + -0.00082755023893878849*g259_1 + 3.7418421325140656e-05*g224_1 + -0.0009210281035986486*g292_1 + -0.016418535698148298*g17_1 + 0.0047352429228796969*g279_1 + -0.074595580883691351*g253_1) + (0.0060303475567825508*g4_1 + -0.00049166069903357136*g16_1 + 0.086644577671932205*g227_1 + -0.0088994604895346833*g72_1 + -0.0057388090992967957*g18_1 + -0.043762219995416837*g74_1 + -0.011059654255555875*g248_1 + -0.00074241051065601475*g289_1 + 0.00040001776619384184*g280_1 + 0.0020986717691697746*g274_1 + 0.010117388746994811*g3_1 + 0.0095697000044535629*g71_1 + 0.020450312025379228*g285_1);
    std::memset(moment_arm + 418, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 424, &a1, 5 * sizeof(double)); L[38] = a1[5]; }
  { const v8d a1 = (0.11101766958416805*g_one_1 + -0.0015444816232241254*g220_1 + 0.023717615046758428*g19_1 + 0.00072223213249632495*g244_1 + -0.0048065477404160631*g17_1 + -0.0050024800273427029*g249_1 + 0.00059231747191871382*g291_1 + 0.0044402349959757441*g256_1) + (0.0079798218547649704*g4_1 + 0.0049954126316480918*g2_1 + -0.0026895084554777733*g227_1 + 0.0020810155040443647*g280_1 + -0.0024813034542557721*g73_1 + -0.0027947660290665198*g289_1 + -0.0034119109417057097*g20_1);
    std::memset(moment_arm + 429, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 435, &a1, 5 * sizeof(double)); L[39] = a1[5]; }
  { const v8d a1 = (0.10420296604274459*g_one_1 + -0.053496466999387537*g17_1 + 0.084427442970077926*g72_1 + -0.13810719181168299*g224_1 + 0.061687585915056582*g69_1 + 0.00050682182754140136*g242_1 + 1.3352209959766194e-05*g259_1 + 0.0023521840781238904*g274_1 + 0.0001808240755507824*g15_1) + (0.0068963691088105459*g4_1 + 0.0042547701878738273*g2_1 + -0.028708876622310094*g220_1 + -0.00090406134949582904*g289_1 + 0.09042258168721086*g249_1 + -0.0010676958874276618*g252_1 + -0.021080516416349455*g280_1 + 0.00099211928555448378*g16_1);
    std::memset(moment_arm + 440, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 446, &a1, 5 * sizeof(double)); L[40] = a1[5]; }
  { const v8d a1 = (0.14153943030040897*g_one_1 + 0.0013677773888225047*g220_1 + 0.0038865528706406843*g2_1 + 0.025165081011776072*g19_1 + -0.0014089090961480694*g255_1 + -5.1994430662788848e-05*g285_1) + (0.0041818195482766982*g4_1 + -0.0004549438480564936*g280_1 + -0.015017232720615944*g17_1 + -0.003934697994660178*g227_1 + 0.00099599475563756862*g67_1 + -0.00048513638730103402*g291_1);
    std::memset(moment_arm + 451, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 457, &a1, 5 * sizeof(double)); L[41] = a1[5]; }
  { const v8d a1 = (0.15696889263373964*g_one_1 + 0.04257014130574574*g220_1 + -0.018184018564973908*g280_1 + -0.14081180062219489*g224_1 + -0.03395944341734157*g244_1 + -0.0074756875214883282*g69_1 + -0.0026072951337350724*g229_1 + -0.0012178457662545853*g73_1) + (-0.00011541187792605546*g75_1 + 0.0065930258878906106*g4_1 + 0.0084646765501430257*g274_1 + 0.0037150504257348125*g2_1 + 0.083192232244979888*g249_1 + 0.097602155260543388*g72_1 + -0.024686704341489878*g17_1);
    std::memset(moment_arm + 462, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 468, &a1, 5 * sizeof(double)); L[42] = a1[5]; }
  { const v8d a1 = (0.13963500623628891*g_one_1 + 0.024061675911017433*g19_1 + 0.0027766936358522704*g2_1 + -0.0011142014688907509*g256_1 + 0.0010374474981920407*g218_1) + (-0.01154774684301673*g17_1 + -0.013291034964295395*g3_1 + -0.0048626277954243171*g72_1 + 0.0032929541424644979*g4_1 + 0.0023193665322437519*g69_1);
    std::memset(moment_arm + 473, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 479, &a1, 5 * sizeof(double)); L[43] = a1[5]; }
  { const v8d a1 = (0.1480844352799803*g_one_1 + 0.021013194988813329*g19_1 + 0.0028596664247313628*g2_1 + 0.0038537461137463924*g4_1 + 0.001477547210689044*g16_1) + (-0.016737344613379956*g3_1 + -0.005372223539685546*g72_1 + -0.01046217280274243*g17_1 + 0.0028953647238998542*g69_1 + -0.00039116910153477096*g289_1);
    std::memset(moment_arm + 484, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 490, &a1, 5 * sizeof(double)); L[44] = a1[5]; }
  { const v8d a1 = (0.13813706300660211*g_one_1 + 0.015873581802469023*g19_1 + -0.004507105212920387*g72_1 + -0.0015870777321478095*g17_1 + -0.00085330295081603919*g230_1) + (-0.026419180701597378*g3_1 + 0.0034226841450876746*g2_1 + 0.0041364217654450983*g20_1 + 0.0015148379016445162*g67_1);
    std::memset(moment_arm + 495, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 501, &a1, 5 * sizeof(double)); L[45] = a1[5]; }
  { const v8d a1 = (0.13020914873535078*g_one_1 + 0.0040246205376601209*g229_1 + -0.0023224428145920753*g292_1 + 0.0022702477783133942*g67_1) + (-0.030320685444223994*g3_1 + 0.0032864663206051406*g2_1 + -0.00053538997116235598*g69_1 + 0.0041836952285397577*g74_1);
    std::memset(moment_arm + 506, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 512, &a1, 5 * sizeof(double)); L[46] = a1[5]; }
  { const v8d a0 = (0.13937944411691178*g_one_0 + 0.025105202319867008*g102_0 + -0.054250611976089762*g17_0 + -0.047544584128926523*g99_0 + -0.019398182065978528*g93_0 + 0.0063364151996237955*g69_0 + 0.091326459696876083*g84_0 + 0.020588644513523185*g116_0 + -0.0054514635838427321*g120_0 + 0.0021891265780643429*g101_0 + -0.0041893390018733993*g18_0 + -0.10822894099244432*g31_0 + 0.0012024245016873218*g70_0 + 0.0017054550871081105*g73_0 + 0.0082945600643434311*g72_0 + -0.0070744626621049161*g86_0 + -0.013836257099931259*g106_0 + -0.099168967593350185*g29_0 + -0.014439972033851299*g80_0 + 0.0053458092867193175*g105_0) + (0.11014530008765835*g24_0 + -0.0048030648697265314*g27_0 + -0.0103539226725653*g74_0 + 0.028740967921374316*g96_0 + -0.012009131817053155*g4_0 + -0.026129565057302188*g82_0 + 0.095862074807236575*g3_0 + -0.013388426707772103*g108_0 + -0.0026242263082477718*g88_0 + 0.02578318796201674*g25_0 + -0.01051830996124577*g91_0 + -0.027402329579323658*g33_0 + 0.0054612643363878485*g7_0 + 0.010879844192999859*g89_0 + 0.00044217462580346069*g75_0 + 0.023746165783928706*g95_0 + 0.0020098858833849549*g67_0 + -0.036393147088563282*g34_0 + 0.015747689948761998*g22_0 + -0.010692396171112712*g19_0); const v8d a1 = (0.13937944411691178*g_one_1 + 0.025105202319867008*g102_1 + -0.054250611976089762*g17_1 + -0.047544584128926523*g99_1 + -0.019398182065978528*g93_1 + 0.0063364151996237955*g69_1 + 0.091326459696876083*g84_1 + 0.020588644513523185*g116_1 + -0.0054514635838427321*g120_1 + 0.0021891265780643429*g101_1 + -0.0041893390018733993*g18_1 + -0.10822894099244432*g31_1 + 0.0012024245016873218*g70_1 + 0.0017054550871081105*g73_1 + 0.0082945600643434311*g72_1 + -0.0070744626621049161*g86_1 + -0.013836257099931259*g106_1 + -0.099168967593350185*g29_1 + -0.014439972033851299*g80_1 + 0.0053458092867193175*g105_1) + (0.11014530008765835*g24_1 + -0.0048030648697265314*g27_1 + -0.0103539226725653*g74_1 + 0.028740967921374316*g96_1 + -0.012009131817053155*g4_1 + -0.026129565057302188*g82_1 + 0.095862074807236575*g3_1 + -0.013388426707772103*g108_1 + -0.0026242263082477718*g88_1 + 0.02578318796201674*g25_1 + -0.01051830996124577*g91_1 + -0.027402329579323658*g33_1 + 0.0054612643363878485*g7_1 + 0.010879844192999859*g89_1 + 0.00044217462580346069*g75_1 + 0.023746165783928706*g95_1 + 0.0020098858833849549*g67_1 + -0.036393147088563282*g34_1 + 0.015747689948761998*g22_1 + -0.010692396171112712*g19_1);
    std::memcpy(moment_arm + 517, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 523, &a1, 5 * sizeof(double)); L[47] = a0[6]; }
  { const v8d a0 = (0.16984270094976286*g_one_0 + -0.085105074279649556*g5_0 + -0.23502450939283065*g98_0 + 0.028823860539130164*g92_0 + 0.033052544765166739*g109_0 + 0.013799560758567744*g78_0 + -0.0097477048165998757*g74_0 + -0.0043827716794029685*g108_0 + -0.023810362925206718*g19_0 + -0.0027508892659398542*g96_0 + -0.0055614324464986114*g95_0 + -0.0059117720935135997*g2_0 + 0.0034076032925671757*g100_0 + 0.0027682308928808574*g120_0 + -0.055779476632021881*g31_0 + -0.01395160819319999*g80_0) + (0.0037731148037981042*g112_0 + 0.014422471626641032*g107_0 + -0.0046210234265750428*g4_0 + -0.0071622575798614219*g116_0 + -0.27823535985637315*g28_0 + 0.079530993279952125*g3_0 + -0.034498350088437275*g17_0 + -0.018427917994916398*g82_0 + 0.0093399905360294494*g72_0 + -0.012935256883347884*g87_0 + -0.0082145111180601492*g106_0 + 0.0026306076576088216*g68_0 + 0.012719228291730285*g102_0 + 0.079849418890459017*g99_0 + 0.1170429249101796*g113_0 + 0.0094543538654000506*g89_0); const v8d a1 = (0.16984270094976286*g_one_1 + -0.085105074279649556*g5_1 + -0.23502450939283065*g98_1 + 0.028823860539130164*g92_1 + 0.033052544765166739*g109_1 + 0.013799560758567744*g78_1 + -0.0097477048165998757*g74_1 + -0.0043827716794029685*g108_1 + -0.023810362925206718*g19_1 + -0.0027508892659398542*g96_1 + -0.0055614324464986114*g95_1 + -0.0059117720935135997*g2_1 + 0.0034076032925671757*g100_1 + 0.0027682308928808574*g120_1 + -0.055779476632021881*g31_1 + -0.01395160819319999*g80_1) + (0.0037731148037981042*g112_1 + 0.014422471626641032*g107_1 + -0.0046210234265750428*g4_1 + -0.0071622575798614219*g116_1 + -0.27823535985637315*g28_1 + 0.079530993279952125*g3_1 + -0.034498350088437275*g17_1 + -0.018427917994916398*g82_1 + 0.0093399905360294494*g72_1 + -0.012935256883347884*g87_1 + -0.0082145111180601492*g106_1 + 0.0026306076576088216*g68_1 + 0.012719228291730285*g102_1 + 0.079849418890459017*g99_1 + 0.1170429249101796*g113_1 + 0.0094543538654000506*g89_1);
    std::memcpy(moment_arm + 528, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 534, &a1, 5 * sizeof(double)); L[48] = a0[6]; }
  { const v8d a0 = (0.15576230880248026*g_one_0 + 0.014744503130220151*g119_0 + -0.068068076138575573*g31_0 + -0.0015703206836296655*g116_0 + -0.00087791112860847239*g20_0 + 0.001835929438890625*g108_0 + -0.028146333962972486*g17_0 + -0.059039104250469619*g33_0 + 0.0098058238480431704*g72_0 + 0.033578154726706208*g25_0 + -0.0097574139661586751*g74_0 + -0.014895403773614774*g110_0 + 0.021974812988325224*g95_0 + 0.0044451389064344704*g105_0 + -0.0036636913899296695*g86_0 + 0.047429664132813854*g28_0 + 0.0017389494842589173*g107_0 + -0.029045497879416151*g26_0) + (-0.0037669934437862852*g24_0 + -0.027063850816851205*g19_0 + 0.014981005158921552*g102_0 + -0.021995663973803495*g99_0 + 0.066800789643819053*g3_0 + 0.023723866801528395*g27_0 + 0.002532471319692405*g82_0 + -0.033952461590703864*g92_0 + -0.0030628305626507263*g22_0 + -0.0061377006444628505*g77_0 + -0.017983731909360649*g80_0 + 0.040246035219528041*g114_0 + 0.0026204918966480383*g67_0 + 0.019455432174951316*g97_0 + 0.015305154718070944*g78_0 + -0.0054533063647430064*g118_0 + -0.099459414927203463*g29_0); const v8d a1 = (0.15576230880248026*g_one_1 + 0.014744503130220151*g119_1 + -0.068068076138575573*g31_1 + -0.0015703206836296655*g116_1 + -0.00087791112860847239*g20_1 + 0.001835929438890625*g108_1 + -0.028146333962972486*g17_1 + -0.059039104250469619*g33_1 + 0.0098058238480431704*g72_1 + 0.033578154726706208*g25_1 + -0.0097574139661586751*g74_1 + -0.014895403773614774*g110_1 + 0.021974812988325224*g95_1 + 0.0044451389064344704*g105_1 + -0.0036636913899296695*g86_1 + 0.047429664132813854*g28_1 + 0.0017389494842589173*g107_1 + -0.029045497879416151*g26_1) + (-0.0037669934437862852*g24_1 + -0.027063850816851205*g19_1 + 0.014981005158921552*g102_1 + -0.021995663973803495*g99_1 + 0.066800789643819053*g3_1 + 0.023723866801528395*g27_1 + 0.002532471319692405*g82_1 + -0.033952461590703864*g92_1 + -0.0030628305626507263*g22_1 + -0.0061377006444628505*g77_1 + -0.017983731909360649*g80_1 + 0.040246035219528041*g114_1 + 0.0026204918966480383*g67_1 + 0.019455432174951316*g97_1 + 0.015305154718070944*g78_1 + -0.0054533063647430064*g118_1 + -0.099459414927203463*g29_1);
    std::memcpy(moment_arm + 539, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 545, &a1, 5 * sizeof(double)); L[49] = a0[6]; }
  { const v8d a0 = (0.16866224359982682*g_one_0 + 0.044581384853228261*g24_0 + 0.015839346431533664*g99_0 + 0.079991256000661121*g3_0 + -0.019987874835521686*g82_0 + 0.00092723581660268109*g116_0 + -0.021771760767818924*g19_0 + -0.03122885276844729*g17_0 + 0.0030170007903981776*g25_0 + -0.07839768902059599*g28_0 + 0.0099070214824678489*g72_0 + 0.0087085283333061432*g21_0 + 0.0015983935250545049*g86_0 + -0.069237429478493373*g31_0 + -0.0058071071613559778*g2_0 + -0.043212131564607646*g5_0 + -0.01279229349691495*g80_0 + 0.0022025922091344781*g67_0 + -0.0061878471458297456*g104_0) + (-0.0015504091515480508*g112_0 + 0.012594441977209629*g102_0 + -0.0067503950523180355*g4_0 + -0.010701837169857408*g74_0 + -0.003438837616822839*g108_0 + 0.020751249264172468*g84_0 + 0.10370222028847909*g113_0 + 0.0011310610360599159*g120_0 + -0.013287052110585297*g87_0 + -0.012228554730125317*g34_0 + -0.02044273755652282*g106_0 + 0.01506211952526502*g78_0 + -0.00066310730559289747*g76_0 + 0.03551366539863373*g6_0 + 0.0012593029011494104*g95_0 + 0.0035656510033097023*g16_0 + 0.0063386854484205309*g105_0 + 0.0057406053103953719*g89_0 + 0.0054131852547109217*g90_0); const v8d a1 = (0.16866224359982682*g_one_1 + 0.044581384853228261*g24_1 + 0.015839346431533664*g99_1 + 0.079991256000661121*g3_1 + -0.019987874835521686*g82_1 + 0.00092723581660268109*g116_1 + -0.021771760767818924*g19_1 + -0.03122885276844729*g17_1 + 0.0030170007903981776*g25_1 + -0.07839768902059599*g28_1 + 0.0099070214824678489*g72_1 + 0.0087085283333061432*g21_1 + 0.0015983935250545049*g86_1 + -0.069237429478493373*g31_1 + -0.0058071071613559778*g2_1 + -0.043212131564607646*g5_1 + -0.01279229349691495*g80_1 + 0.0022025922091344781*g67_1 + -0.0061878471458297456*g104_1) + (-0.0015504091515480508*g112_1 + 0.012594441977209629*g102_1 + -0.0067503950523180355*g4_1 + -0.010701837169857408*g74_1 + -0.003438837616822839*g108_1 + 0.020751249264172468*g84_1 + 0.10370222028847909*g113_1 + 0.0011310610360599159*g120_1 + -0.013287052110585297*g87_1 + -0.012228554730125317*g34_1 + -0.02044273755652282*g106_1 + 0.01506211952526502*g78_1 + -0.00066310730559289747*g76_1 + 0.03551366539863373*g6_1 + 0.0012593029011494104*g95_1 + 0.0035656510033097023*g16_1 + 0.0063386854484205309*g105_1 + 0.0057406053103953719*g89_1 + 0.0054131852547109217*g90_1);
    std::memcpy(moment_arm + 550, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 556, &a1, 5 * sizeof(double)); L[50] = a0[6]; }
  { const v8d a1 = (0.16319374818907079*g_one_1 + -0.00017254294702921696*g69_1 + 0.0082406321532403418*g3_1 + 0.00034428792305349083*g295_1 + -0.0037814638788647458*g74_1 + -0.0064341225058615588*g17_1) + (-0.026914516474557674*g19_1 + 0.00037416349260522603*g280_1 + 0.00079540932734571863*g15_1 + 0.0015410006487466858*g18_1 + 0.002677160664029401*g229_1 + 0.0018952183285911438*g224_1);
    std::memset(moment_arm + 561, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 567, &a1, 5 * sizeof(double)); L[51] = a1[5]; }
  { const v8d a1 = (0.17745423565073179*g_one_1 + 0.013246650292477296*g3_1 + 0.0058991743602023819*g72_1 + -0.0042766155498672551*g74_1 + 0.00077394117939191375*g285_1) + (-0.031176418399920237*g19_1 + -0.0060659207789059708*g17_1 + 0.0018427896308484432*g16_1 + 0.0012799524761196752*g75_1);
    std::memset(moment_arm + 572, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 578, &a1, 5 * sizeof(double)); L[52] = a1[5]; }
  { const v8d a1 = (0.19276048409560206*g_one_1 + -0.0028109787648471149*g69_1 + 0.0045261183980935113*g3_1 + 0.0005453354003348629*g295_1) + (-0.030853295527772218*g19_1 + 0.0011368470949650832*g280_1 + 0.0016625051467250877*g2_1 + -0.00026749274104077993*g74_1);
    std::memset(moment_arm + 583, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 589, &a1, 5 * sizeof(double)); L[53] = a1[5]; }
  { const v8d a1 = (0.087869980944185369*g_one_1 + 0.014643780311148375*g4_1 + 0.003401044758462556*g253_1 + -0.0034394184283632924*g223_1 + -0.0074549247935674252*g15_1 + 0.0011395467567401555*g247_1 + -0.0023033659687782247*g222_1 + -0.0054866482259867781*g20_1 + 0.0015910795801112273*g221_1 + -0.010728814695207872*g291_1 + 0.0026267086160523378*g228_1 + -0.0030896451560659833*g286_1 + 0.011811163037600231*g69_1 + 0.001657364783182233*g66_1 + -0.0024107415751879152*g292_1) + (-0.015045319120065433*g17_1 + 0.01503235236644344*g2_1 + -0.0047305486616303818*g19_1 + 0.0022074995931857652*g284_1 + -0.008326104230914835*g220_1 + -0.015057373243495886*g18_1 + 0.0038699350628732996*g73_1 + 0.0014017431853493233*g74_1 + -0.00098515929778973253*g219_1 + 0.013036189743163708*g255_1 + 0.0085290728077761589*g70_1 + 0.00075072079704669077*g242_1 + 0.0022308727426337059*g244_1 + 0.00014664138562204781*g295_1 + 0.0049744770164780209*g229_1);
    std::memset(moment_arm + 594, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 600, &a1, 5 * sizeof(double)); L[54] = a1[5]; }
  { const v8d a1 = (0.17356621612999892*g_one_1 + 0.0069679171336001168*g74_1 + 0.00024494054812902678*g69_1 + -0.0060161974996631746*g19_1 + -0.0055558098165239735*g18_1 + -0.00015339387219721797*g225_1 + 0.00049330848389187473*g220_1 + 0.0040093765235933035*g226_1 + 0.0012273666634509152*g66_1 + 0.0029747427038394349*g70_1 + -0.0034551823471286802*g292_1 + 0.0040975032207306904*g256_1) + (-0.0089510384405577393*g17_1 + 0.011095552258008522*g2_1 + 0.010534497562897094*g4_1 + 0.00073486892350355657*g285_1 + -0.0037437352867697518*g15_1 + 0.0010315201930348888*g75_1 + -0.00059606750620098351*g68_1 + -0.0049801106251140198*g3_1 + -0.0020491538512592291*g223_1 + 0.00054129728991675981*g278_1 + -0.0036889695994661463*g20_1);
    std::memset(moment_arm + 605, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 611, &a1, 5 * sizeof(double)); L[55] = a1[5]; }
  { const v8d a1 = (0.14838254604080264*g_one_1 + 0.010949119986949701*g74_1 + -0.010288938489065579*g17_1 + -0.0077535390780109782*g19_1 + -0.0097260418265631473*g18_1 + 0.0045063713564514598*g251_1 + 0.0055265558271342559*g73_1 + -0.0039599355335162723*g15_1 + 0.0018892639919294116*g69_1 + -0.0069315710061313802*g20_1 + 0.0082001858345322146*g70_1 + 0.0010581670720069755*g217_1) + (-0.0053066784121569279*g3_1 + 0.012015745383368479*g2_1 + 0.012032792953201712*g4_1 + 0.00092905729632579903*g285_1 + 0.0001029954243784302*g218_1 + -0.00010331132460065307*g72_1 + 0.0027665820486616061*g75_1 + -0.0010270174925429774*g68_1 + 0.00024142907899367958*g221_1 + -0.0015037010045402587*g294_1 + -0.0059377847249093884*g225_1 + -0.0033777944487118124*g222_1);
    std::memset(moment_arm + 616, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 622, &a1, 5 * sizeof(double)); L[56] = a1[5]; }
  { const v8d a1 = (0.13999229537492067*g_one_1 + -0.0029830961808690591*g74_1 + 0.0082804691484007382*g4_1 + -0.0045920405800400042*g223_1 + -0.0091616812387527204*g17_1 + -0.0025592899130964758*g15_1 + -0.0045612834519968759*g18_1 + -0.00038231210222328951*g243_1 + 0.0069313380187213417*g227_1 + 0.0040434519696275267*g229_1 + 0.0071709396414395615*g256_1) + (-0.012571568159364178*g3_1 + 0.010529600748332412*g2_1 + -0.004356895770962127*g72_1 + 0.0022983462408386304*g284_1 + 0.00030243956614094152*g285_1 + 0.00017522143559512698*g222_1 + 0.0028123885076645067*g69_1 + 0.0034850822615111973*g226_1 + -0.0067529052712627024*g292_1 + 0.0030783463317587837*g70_1);
    std::memset(moment_arm + 627, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 633, &a1, 5 * sizeof(double)); L[57] = a1[5]; }
  { const v8d a1 = (0.12632554492856576*g_one_1 + -0.020667626805742297*g3_1 + 0.00053559962318527605*g227_1 + -0.0090907476561897325*g72_1 + 0.00081378144774099681*g280_1 + -0.0034684571517484505*g16_1 + -0.010412467767321963*g223_1 + -0.00037899202789234781*g283_1 + 4.2966483861518393e-05*g295_1 + 0.0033801966979063662*g222_1 + 0.0095850386674142113*g71_1 + 0.0041866755961794426*g19_1 + -0.003256270030824922*g291_1) + (0.00018571314528880573*g20_1 + 0.011281153365361098*g2_1 + 0.0085802372734779773*g4_1 + -0.029455382212755569*g292_1 + -0.0064759711885774684*g229_1 + 0.0057760552994774025*g284_1 + 0.039008494722112604*g256_1 + -0.0010460968377591375*g15_1 + -0.0011592528692242852*g259_1 + -0.010786981693608066*g18_1 + 0.008709112439198476*g294_1 + 0.0070645991556004669*g73_1);
    std::memset(moment_arm + 638, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 644, &a1, 5 * sizeof(double)); L[58] = a1[5]; }
  { const v8d a1 = (0.10806874034201941*g_one_1 + 0.010103909010906824*g256_1 + 0.014645242520577554*g69_1 + -0.016350045648880662*g71_1 + -0.0082396486185728618*g3_1 + -0.0023292087671239249*g20_1 + -0.0015671134829819131*g15_1 + 0.014364605928116432*g288_1 + 0.00034604756989141481*g218_1 + -0.0024640370561738647*g294_1 + -0.0073840439017967534*g255_1) + (-0.019847943272352966*g17_1 + 0.010971828734870917*g2_1 + 0.010297910169325027*g4_1 + 0.019034125072836732*g226_1 + -0.0027445545765559342*g72_1 + -0.0036173526628551834*g220_1 + 0.0016521706764343672*g222_1 + 0.00086363288830983457*g279_1 + -0.01216887346226837*g284_1 + 0.0014192530003784977*g230_1 + -0.0030756427647405742*g18_1);
    std::memset(moment_arm + 649, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 655, &a1, 5 * sizeof(double)); L[59] = a1[5]; }
  { const v8d a1 = (0.09315877706334319*g_one_1 + 3.5301682717440235e-06*g274_1 + 0.014045317956737226*g2_1 + -0.0019869033534603182*g19_1 + 0.017308766582397841*g3_1 + 8.7899297896903021e-05*g242_1 + -0.0057011711653609564*g20_1 + 0.00065297039062390204*g67_1 + -0.00039866840403668348*g279_1 + 0.0050789903196014809*g66_1 + 0.012951499842115521*g70_1 + 0.0016908677948509567*g252_1 + 0.002266794079587501*g227_1 + 0.0037816573019422962*g281_1 + -0.00091498997929429881*g291_1 + -0.00062460016921501624*g294_1) + (-0.011955670537629567*g18_1 + 0.013839796477325668*g4_1 + -0.0011120359171408259*g72_1 + -0.00029938818582666551*g249_1 + -0.0093555757120032876*g17_1 + 0.00069006645348913289*g285_1 + 0.0067495492404286931*g73_1 + 0.00015548144988738062*g222_1 + -0.0079145490701789875*g15_1 + -0.0010194872932794154*g68_1 + -0.0067051052843509901*g225_1 + -0.00096754092612443172*g276_1 + -0.0055557207906123751*g221_1 + -0.0015294651188885895*g216_1 + 0.0012068835300714413*g230_1);
    std::memset(moment_arm + 660, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 666, &a1, 5 * sizeof(double)); L[60] = a1[5]; }
  { const v8d a1 = (0.10960419230259845*g_one_1 + 0.00065066127836002218*g220_1 + 0.014835303185936129*g2_1 + 0.00011372818869865523*g218_1 + -0.0001302627916489056*g274_1 + -0.011014370345540292*g17_1 + -0.0070707035476625978*g15_1 + 0.0004843747944508368*g284_1 + -0.0039755746328562457*g249_1 + 0.0027236697676880288*g216_1 + 0.004457223627491012*g226_1 + 0.00090901220449426078*g278_1 + 0.0017153848180389922*g280_1 + 0.0029464615106719822*g73_1 + -0.0025603315458946241*g292_1) + (-0.011067333136799791*g18_1 + 0.012521930587662832*g4_1 + -0.0027198171992369991*g289_1 + -0.0030448378539296331*g287_1 + 0.013510427769020729*g3_1 + -0.0060363963223625033*g74_1 + -0.0030250053729758801*g223_1 + -7.1941210837239467e-05*g251_1 + 0.003432569947129197*g253_1 + 0.0080900894464779639*g70_1 + 0.0089548306495720164*g256_1 + -0.0021990842566022221*g20_1 + -0.0024513247770276314*g275_1 + -0.00035075300406264923*g219_1);
    std::memset(moment_arm + 671, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 677, &a1, 5 * sizeof(double)); L[61] = a1[5]; }
  { const v8d a1 = (0.069572182077032738*g_one_1 + 0.0020338858158611057*g220_1 + 0.014806649057972587*g2_1 + 0.00044942756124782758*g242_1 + -0.0051583545297041837*g20_1 + -0.0019378285623766957*g19_1 + 0.0079705365070204207*g3_1 + -0.0068643222112683639*g69_1 + 0.00083688731463800589*g284_1 + 0.0036982577336502199*g226_1 + 0.0010757785312054374*g270_1 + 0.003718277067390135*g258_1) + (-0.01068819018639932*g18_1 + 0.014916963429265235*g4_1 + 0.004554817613066176*g289_1 + -0.0014210331578339225*g287_1 + -0.00050764140234508474*g224_1 + -0.00046080370514730456*g249_1 + -0.005292442056554672*g15_1 + -0.0028655218423130698*g223_1 + 0.0059269623562030957*g70_1 + -0.0010142322045045898*g68_1 + -0.005288343057224104*g292_1 + 0.0029639052612313518*g73_1);
    std::memset(moment_arm + 682, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 688, &a1, 5 * sizeof(double)); L[62] = a1[5]; }
  { const v8d a1 = (0.092361352698177038*g_one_1 + -0.008981844348677305*g20_1 + -0.010525880556632878*g2_1 + 0.0036541275866262663*g70_1 + -0.014713213780803725*g69_1 + -0.0074015361807005693*g227_1 + 0.0023611656373560505*g15_1 + 0.0044262685502845824*g289_1 + 0.00096869293613083729*g295_1 + 0.0011658761718553203*g73_1) + (0.059854005539370161*g3_1 + 0.0014139893629133973*g244_1 + 0.0029135707294001317*g18_1 + -0.0041293449600124515*g292_1 + 0.0076841181517891856*g249_1 + 0.0019730294367657606*g68_1 + -0.0040729426872828135*g280_1 + 0.014006391792384807*g17_1 + -0.0010840324416225594*g278_1);
    std::memset(moment_arm + 693, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 699, &a1, 5 * sizeof(double)); L[63] = a1[5]; }
  { const v8d a1 = (0.10727212207151879*g_one_1 + -0.0059029031166689542*g20_1 + -0.0092762196803583274*g2_1 + 0.0008938799687981837*g229_1 + 0.0026426211217628233*g16_1 + -0.01322348803189731*g74_1) + (0.085306811107992375*g3_1 + -0.0074512078625834097*g69_1 + 0.00047020356636423663*g4_1 + 0.005925684050793357*g70_1 + 0.0030816991197714074*g224_1);
    std::memset(moment_arm + 704, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 710, &a1, 5 * sizeof(double)); L[64] = a1[5]; }
  { const v8d a1 = (0.10242720819885642*g_one_1 + -0.0064234193206155069*g69_1 + -0.0077970890386103008*g2_1 + -0.0062887749111890127*g20_1 + -0.00041046837443973084*g229_1 + 0.0011661261324728523*g219_1 + -0.013534926140094647*g74_1) + (0.072079694227316665*g3_1 + 0.0017570180760558681*g75_1 + -0.0023797459439002162*g4_1 + -0.00079495040066098182*g246_1 + 0.013051275624802853*g19_1 + 0.0058665000041986035*g70_1);
    std::memset(moment_arm + 715, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 721, &a1, 5 * sizeof(double)); L[65] = a1[5]; }
  { const v8d a1 = (0.089122058405541812*g_one_1 + -0.012145840975619675*g20_1 + -0.0079328841005514641*g69_1 + -0.0012410649188842355*g243_1 + -0.0027392883334447435*g249_1 + 0.0084701862753587404*g17_1 + 0.0010910202297975732*g280_1 + 0.0057655896475918237*g73_1 + -0.002544506913053619*g283_1 + -0.0066788413052626299*g4_1 + -0.016757954687237939*g229_1) + (0.043108470829151889*g3_1 + -0.011728770824699456*g2_1 + 0.0061809430448025145*g70_1 + 0.0060986104470848118*g256_1 + -0.0018134171610291682*g228_1 + 0.010262465769351329*g75_1 + 0.0019365094570209945*g66_1 + 0.003323725618563405*g219_1 + 0.0010311079006121813*g220_1 + 0.010983527426828279*g19_1);
    std::memset(moment_arm + 726, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 732, &a1, 5 * sizeof(double)); L[66] = a1[5]; }
  { const v8d a1 = (0.091052795741133938*g_one_1 + 0.0027793616334225182*g73_1 + 0.0079770301564307585*g67_1 + 1.9338776165187145e-05*g289_1 + -0.0065654144022626844*g16_1 + 0.00039794971018928204*g279_1 + -0.010616243938079056*g15_1 + 0.00045405309804159107*g230_1 + 0.011045232314445277*g71_1 + 0.00018689287354360643*g255_1 + 0.0099136164326287784*g284_1 + 0.011509442698279807*g4_1 + -0.024610619256344529*g18_1 + 0.0021324422144315181*g244_1 + -0.0029184754309148678*g220_1 + -0.013731735530594336*g252_1) + (-0.021602044178405354*g3_1 + -0.0015824346941772456*g70_1 + 0.0027898414809563307*g225_1 + -0.0076980185554914619*g248_1 + 0.0035348187796360674*g278_1 + 0.00024136841865285167*g288_1 + -0.0092245274295004141*g19_1 + 0.00076000230283910977*g72_1 + 0.011285264085938444*g2_1 + -0.00033259485391723832*g274_1 + -0.0054104628182576383*g283_1 + -0.012288793818339359*g20_1 + 0.010940706189944164*g74_1 + 0.0039574267650379497*g68_1 + 0.0023996864250507379*g286_1);
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
  { const v8d a1 = (0.1162491733308286*g_one_1 + 0.0017880904253448364*g75_1 + -0.0015212855071285488*g287_1 + 8.0280156847778577e-05*g216_1 + 0.0039200150384532144*g273_1 + 0.00055020982181753846*g71_1 + -0.016477628993415004*g243_1 + 0.010311511577185935*g73_1 + 0.021398452162351516*g219_1 + 0.0044569733258832114*g20_1 + 0.0027477722322467209*g229_1 + -0.00064723586865370053*g289_1 + -0.00038345747725953807*g19_1) + (-0.02440482452541038*g4_1 + -0.0011542999123590151*g244_1 + 0.0031270502999528435*g66_1 + -0.00071038137786596589*g225_1 + -0.0208266284012503*g2_1 + -0.015237042861813271*g3_1 + 0.0044260114520036668*g17_1 + 0.01092745825301813*g70_1 + -0.0026059679271194323*g241_1 + -0.0022373005096017165*g284_1 + 0.0029751174277800694*g220_1 + 0.0025371376106306126*g223_1);
    std::memset(moment_arm + 803, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 809, &a1, 5 * sizeof(double)); L[73] = a1[5]; }
  { const v8d a1 = (0.11844492735459632*g_one_1 + -0.025129606747833023*g2_1 + -0.0082319880330347043*g3_1 + 0.0018518448664789251*g17_1 + 0.0019104997433429397*g221_1 + 0.001223182247972403*g252_1 + 0.010451554070810571*g228_1 + 0.00089634996285656624*g230_1 + -0.0095766966119518373*g73_1 + -0.0015987012328949717*g15_1 + -0.0015415791551807842*g283_1) + (-0.024878029832348394*g4_1 + 0.0084673678190704052*g68_1 + -0.0056344399060740107*g254_1 + -9.292677140359599e-06*g75_1 + -0.0020010432347564401*g67_1 + 0.0018625621679692276*g278_1 + 0.0018569842053449762*g66_1 + 0.015076572361656255*g225_1 + -0.0026396835895730773*g288_1 + 0.0003069244371176765*g294_1);
    std::memset(moment_arm + 814, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 820, &a1, 5 * sizeof(double)); L[74] = a1[5]; }
  { const v8d a1 = (0.11909785774291502*g_one_1 + -0.023051243737646665*g4_1 + 0.0013274451205255325*g279_1 + 0.010307458561895388*g219_1 + 0.00023778368920201153*g295_1 + -0.0055499874373101379*g286_1 + -0.00069722164857561469*g74_1 + 0.00023053770988363395*g245_1 + -0.002972513938988371*g278_1 + 0.0022760769727131949*g257_1 + -0.0018443332053863948*g284_1 + -0.00038317103172964286*g224_1 + 0.0091321891973702093*g250_1 + 0.0071860642303024289*g247_1 + 0.00043981697666137552*g272_1) + (-0.023730508930462125*g2_1 + 0.00041021638119618001*g19_1 + -0.0080709864407908505*g3_1 + 0.0035695363921185515*g254_1 + 5.4181954675696225e-05*g226_1 + -0.00036708945268882118*g15_1 + -0.0038442611189009944*g243_1 + 0.0012438551572325667*g223_1 + -0.0037440187760439201*g67_1 + -0.0079139733267132081*g71_1 + 0.00010034841625137004*g274_1 + 0.0017393315315317424*g229_1 + -0.00085427006294893195*g17_1 + 0.00087874716661838319*g239_1);
    std::memset(moment_arm + 825, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 831, &a1, 5 * sizeof(double)); L[75] = a1[5]; }
  { const v8d a1 = (0.14231247220402973*g_one_1 + -0.024007763364639171*g4_1 + -0.010637418620020879*g225_1 + 0.00018453255604255683*g295_1 + -0.0031909411658428781*g226_1 + 0.0062017059115024907*g247_1 + -0.0034034173498247453*g16_1 + 0.00053826392101568503*g270_1 + -0.0044793078110146201*g283_1 + 0.017598119386501396*g254_1) + (-0.025075324151714484*g2_1 + 0.0077487487525613437*g219_1 + -0.0024758916064649022*g3_1 + -0.021387012076275587*g286_1 + -0.0027670365062369764*g67_1 + -0.0010867660537896057*g273_1 + 0.0037316678211110873*g228_1 + -0.0033756897870230789*g18_1 + 0.025082346232108758*g250_1);
    std::memset(moment_arm + 836, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 842, &a1, 5 * sizeof(double)); L[76] = a1[5]; }
  { const v8d a1 = (0.13702768362040874*g_one_1 + -0.022070629335599508*g4_1 + 0.0048064851694220529*g250_1 + -0.017604889081575287*g16_1 + 0.0060421094327071795*g70_1 + -0.0025651758927928659*g291_1 + -0.00072455351437487642*g74_1 + 0.0020059096730458159*g239_1 + 9.8292639242005941e-05*g244_1 + -0.0014963916270082991*g67_1 + 0.0024101315288816106*g222_1) + (-0.021273207732021172*g2_1 + -0.00062449922333085049*g243_1 + 0.0012617487453210916*g230_1 + 0.015494614862044445*g68_1 + -0.0064334353364156084*g293_1 + -0.00044668152160643615*g280_1 + 0.01249735344777772*g257_1 + -0.0011115332412399083*g3_1 + 0.00086577256318387042*g249_1 + -0.0018908868647398199*g18_1 + -0.0021263949587997494*g282_1);
    std::memset(moment_arm + 847, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 853, &a1, 5 * sizeof(double)); L[77] = a1[5]; }
  { const v8d a1 = (0.095569274998744916*g_one_1 + -0.021949135020791731*g4_1 + 0.0087898449949352104*g225_1 + -5.466098088532096e-05*g273_1 + 0.00033381622578192849*g295_1 + 0.0001380533006608781*g72_1 + -0.0031041137858471499*g20_1 + 0.0036075327869102801*g228_1 + 0.0099367007375615289*g248_1 + -0.0059140046091147869*g71_1 + -0.0022262669669770034*g3_1 + 0.0012457116015030631*g17_1 + -0.0018029485381495164*g15_1 + 0.0025356888519013302*g75_1) + (-0.022705598096231419*g2_1 + -0.00048729172327229535*g219_1 + -0.012023842938927441*g16_1 + 0.0075890020750033248*g250_1 + -0.0012951179521305865*g229_1 + 0.00097169737700152623*g74_1 + 0.0063442671839460752*g275_1 + -0.0046225272565112744*g252_1 + 0.012281735081611707*g68_1 + -2.9218221645802485e-06*g274_1 + -0.0036986242309063572*g279_1 + -0.0094914891283777534*g281_1 + 0.0013935900926752656*g66_1);
    std::memset(moment_arm + 858, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 864, &a1, 5 * sizeof(double)); L[78] = a1[5]; }
  { const v8d a1 = (0.113638441335471*g_one_1 + -0.01911515746072296*g4_1 + 0.0018654110595232862*g221_1 + -0.0027215330779526451*g257_1 + -0.0015691326036427779*g291_1 + -0.0018253360881809091*g244_1 + 0.0023933075919173028*g66_1 + 0.0013939302788312292*g230_1 + -0.00113338257985225*g74_1 + 0.0084986299042356626*g228_1 + -0.00074055379008651978*g227_1 + -0.0015592531590919087*g284_1) + (-0.019838816192965979*g2_1 + 0.0036540482956609181*g69_1 + -0.0014166632533145374*g219_1 + 0.0044215513130951038*g70_1 + -0.015669999114320512*g16_1 + 0.0019309118934766484*g248_1 + -1.2658998881760881e-05*g279_1 + 0.003520278304367081*g225_1 + 0.0011902691951039201*g72_1 + 0.013237851417268033*g68_1 + 0.00062661233460643883*g274_1 + -0.00087337167190192566*g287_1);
    std::memset(moment_arm + 869, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 875, &a1, 5 * sizeof(double)); L[79] = a1[5]; }
  { const v8d a1 = (0.057448281853319641*g_one_1 + -0.01562093952909906*g4_1 + 0.0066183585663137472*g222_1 + 0.0031726568000330661*g71_1 + 0.0025476781806598793*g17_1 + 0.0077130964273832816*g19_1 + -0.019789845159165168*g251_1 + 0.0048689351031667646*g228_1 + -0.001592763549918846*g293_1) + (0.012565765251999816*g3_1 + -0.017903723735573349*g2_1 + -0.0058276543004074375*g74_1 + 0.0024805473013718607*g66_1 + 0.012203476941932634*g225_1 + 0.0020417299754544854*g68_1 + -0.00037943812886735787*g280_1 + 0.00061408573383541312*g295_1 + 0.0057419963776219329*g283_1);
    std::memset(moment_arm + 880, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 886, &a1, 5 * sizeof(double)); L[80] = a1[5]; }
  { const v8d a1 = (0.037199383928831625*g_one_1 + 0.00095929729017872807*g75_1 + 0.0030447392678209623*g254_1 + -0.0067119311340543093*g225_1 + 0.00047075261924116589*g292_1 + 0.0020686071480918869*g216_1 + -0.012610378762051773*g4_1 + 0.0093916135646497402*g70_1 + -0.0029309087490361719*g276_1 + 0.00036970671128350798*g274_1 + -0.011097521450473945*g255_1 + 0.0027005527257158257*g15_1 + 0.0042644329999193976*g288_1) + (0.021236054593630184*g3_1 + -0.014778813758578511*g2_1 + 0.0012985144407455216*g20_1 + 0.0010771378610969313*g257_1 + 0.0051403245198481636*g16_1 + 0.010106064341414325*g73_1 + 0.010359026137261956*g19_1 + -0.0087956157798328508*g74_1 + -0.00076758092969578652*g249_1 + -0.00050893202946535509*g244_1 + 0.0025308674281596557*g71_1 + -0.0014524514444762512*g67_1 + -0.00043016187326383774*g219_1);
    std::memset(moment_arm + 891, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 897, &a1, 5 * sizeof(double)); L[81] = a1[5]; }
  { const v8d a1 = (0.39301401992035473*g_one_1 + -0.022726489452261571*g3_1 + 3.3580948373612267e-05*g4_1 + 0.0064505761963830708*g218_1 + -0.00050993446149439692*g62_1 + 0.0015854747048530838*g214_1 + -0.0068102179502176332*g20_1 + 0.0015319899373271155*g0_1 + -0.003323405788122459*g66_1) + (-0.025688990657068134*g1_1 + 0.00477417367876775*g73_1 + 0.0044832822912369719*g12_1 + -0.018010270841932883*g18_1 + -0.00034072478080398325*g213_1 + -0.016710805969772771*g13_1 + 0.0027941731667783473*g74_1 + -8.3402520576651175e-05*g211_1 + 0.003919134872382944*g221_1);
    std::memset(moment_arm + 902, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 908, &a1, 5 * sizeof(double)); L[82] = a1[5]; }
  { const v8d a1 = (0.35352503809417579*g_one_1 + -0.039543911481044185*g19_1 + 0.00098851427431825541*g214_1 + -0.0028835086270963596*g227_1 + 0.0063902729850981912*g224_1 + 0.0024967555865351562*g228_1 + 0.0044625599574396706*g229_1 + 0.0024318602900161813*g12_1 + 0.010748889251046974*g3_1 + -0.00058563472061855314*g11_1) + (-0.026058255851233308*g1_1 + 0.0044410487637062731*g0_1 + -0.02178241391038584*g13_1 + -0.00039120061642218919*g69_1 + 0.0010513260601565484*g67_1 + -0.0078749889504705958*g17_1 + -0.00041948935654077124*g213_1 + -0.00027693154455234431*g215_1 + 0.0013758409759407374*g65_1 + 0.003874222283257294*g63_1);
    std::memset(moment_arm + 913, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 919, &a1, 5 * sizeof(double)); L[83] = a1[5]; }
  { const v8d a1 = (0.35352503809417579*g_one_1 + -0.039543911481044185*g19_1 + 0.00098851427431825541*g214_1 + -0.0028835086270963596*g227_1 + 0.0063902729850981912*g224_1 + 0.0024967555865351562*g228_1 + 0.0044625599574396706*g229_1 + 0.0024318602900161813*g12_1 + 0.010748889251046974*g3_1 + -0.00058563472061855314*g11_1) + (-0.026058255851233308*g1_1 + 0.0044410487637062731*g0_1 + -0.02178241391038584*g13_1 + -0.00039120061642218919*g69_1 + 0.0010513260601565484*g67_1 + -0.0078749889504705958*g17_1 + -0.00041948935654077124*g213_1 + -0.00027693154455234431*g215_1 + 0.0013758409759407374*g65_1 + 0.003874222283257294*g63_1);
    std::memset(moment_arm + 924, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 930, &a1, 5 * sizeof(double)); L[84] = a1[5]; }
  { const v8d a1 = (0.28810482745662963*g_one_1 + 0.018858723428750376*g1_1 + 0.002316555133211154*g4_1 + 1.225328770015525e-05*g14_1 + 0.007683884841880438*g227_1 + -0.024041041142686764*g74_1) + (0.040383697740527719*g3_1 + -0.0014963532796749772*g220_1 + 0.0012621978471176545*g20_1 + -0.0090516803515194519*g72_1 + 0.028051818099328107*g19_1 + 0.0031334058079304024*g2_1);
    std::memset(moment_arm + 935, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 941, &a1, 5 * sizeof(double)); L[85] = a1[5]; }
  { const v8d a1 = (0.29944073107803498*g_one_1 + 0.018501387610506386*g1_1 + -0.00090018278279695467*g220_1 + -0.010539570581817407*g74_1 + 0.0016714269032897184*g256_1) + (0.030756245851734327*g3_1 + -0.001256113338338406*g229_1 + 0.0064687915319943511*g19_1 + 0.001298392582581722*g14_1);
    std::memset(moment_arm + 946, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 952, &a1, 5 * sizeof(double)); L[86] = a1[5]; }
  { const v8d a1 = (0.32608139225169236*g_one_1 + 0.01839060678965734*g1_1 + 0.0038838402511281126*g4_1 + 0.0015329945277652035*g14_1 + 0.0036453391100054271*g227_1 + -0.013535345170157967*g74_1) + (0.030045319495507688*g3_1 + -0.0010945457504662037*g220_1 + -0.001109833491462835*g20_1 + -0.0037829010172135999*g72_1 + 0.014544553418980635*g19_1);
    std::memset(moment_arm + 957, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 963, &a1, 5 * sizeof(double)); L[87] = a1[5]; }
  { const v8d a1 = (0.32204768950797774*g_one_1 + 0.018521603599392124*g1_1 + -0.00063741170743471275*g244_1 + -0.0035538838905914355*g20_1 + 0.00019703181324897873*g259_1 + 0.0010754891591418817*g224_1) + (0.032634702960076666*g3_1 + 0.00013605496168904929*g258_1 + 0.0053475158498315096*g4_1 + 0.0012302702320920132*g14_1 + -0.0070671311561727405*g74_1);
    std::memset(moment_arm + 968, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 974, &a1, 5 * sizeof(double)); L[88] = a1[5]; }
  { const v8d a0 = (0.27473928162242328*g_one_0 + -0.012299197293750322*g47_0 + -0.23129671693930234*g178_0 + 0.008469565294315657*g105_0 + 0.0021780119662118736*g51_0 + 0.2229933639508552*g56_0 + 0.00035919893970113318*g143_0 + 0.0018072680735576707*g205_0 + 0.043064609715478701*g23_0 + -0.048521251457008446*g184_0 + -0.31255503739356205*g55_0 + -0.04709237381797686*g180_0 + 0.017071491960296222*g181_0 + -0.022798456221942688*g32_0 + -0.085652956409495482*g28_0 + -0.074341680889516024*g96_0 + 0.0097344296236413497*g103_0 + 0.088318937353364962*g34_0 + 0.016957608621079867*g86_0 + 0.01167299666686376*g100_0 + -0.038425082349007204*g201_0 + 0.13482901904562691*g29_0) + (0.51688034983982345*g187_0 + 0.016101125413244436*g37_0 + 0.0098155049961709748*g50_0 + -0.0059730836101250708*g139_0 + 0.074281077347716842*g9_0 + 0.11137610658456867*g6_0 + -0.1345991525919383*g26_0 + 0.056800650604144291*g111_0 + -0.021155510305811354*g2_0 + -0.0051261311955547919*g157_0 + 0.0052218254254273967*g19_0 + 0.050913062894650189*g8_0 + -0.0048834226777370905*g67_0 + -0.012661512833969331*g74_0 + 0.019735371930020146*g99_0 + -0.010771670143358801*g122_0 + 0.33058978263384586*g182_0 + 0.0090044308788486752*g68_0 + 0.019972446065302612*g91_0 + -0.018761126412976746*g166_0 + -0.13325117354676985*g183_0 + 0.050071516818713878*g83_0); const v8d a1 = (0.27473928162242328*g_one_1 + -0.012299197293750322*g47_1 + -0.23129671693930234*g178_1 + 0.008469565294315657*g105_1 + 0.0021780119662118736*g51_1 + 0.2229933639508552*g56_1 + 0.00035919893970113318*g143_1 + 0.0018072680735576707*g205_1 + 0.043064609715478701*g23_1 + -0.048521251457008446*g184_1 + -0.31255503739356205*g55_1 + -0.04709237381797686*g180_1 + 0.017071491960296222*g181_1 + -0.022798456221942688*g32_1 + -0.085652956409495482*g28_1 + -0.074341680889516024*g96_1 + 0.0097344296236413497*g103_1 + 0.088318937353364962*g34_1 + 0.016957608621079867*g86_1 + 0.01167299666686376*g100_1 + -0.038425082349007204*g201_1 + 0.13482901904562691*g29_1) + (0.51688034983982345*g187_1 + 0.016101125413244436*g37_1 + 0.0098155049961709748*g50_1 + -0.0059730836101250708*g139_1 + 0.074281077347716842*g9_1 + 0.11137610658456867*g6_1 + -0.1345991525919383*g26_1 + 0.056800650604144291*g111_1 + -0.021155510305811354*g2_1 + -0.0051261311955547919*g157_1 + 0.0052218254254273967*g19_1 + 0.050913062894650189*g8_1 + -0.0048834226777370905*g67_1 + -0.012661512833969331*g74_1 + 0.019735371930020146*g99_1 + -0.010771670143358801*g122_1 + 0.33058978263384586*g182_1 + 0.0090044308788486752*g68_1 + 0.019972446065302612*g91_1 + -0.018761126412976746*g166_1 + -0.13325117354676985*g183_1 + 0.050071516818713878*g83_1);
    std::memcpy(moment_arm + 979, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 985, &a1, 5 * sizeof(double)); L[89] = a0[6]; }
  { const v8d a0 = (0.2731287727919155*g_one_0 + -0.081199031955779918*g187_0 + 0.11813626380632239*g9_0 + 0.0076039093569542924*g105_0 + -0.026057686172391653*g25_0 + 0.093899656612461566*g55_0 + -0.0022953587452464474*g157_0 + -0.012054719324202486*g95_0 + -0.025239038291381324*g94_0 + 0.058722930685422406*g34_0 + -0.051901881701030154*g166_0 + 0.006868410804076938*g19_0 + -0.015795470194206913*g181_0 + -0.30214112927973891*g54_0 + -0.023431513721749425*g110_0 + 0.014413770133822454*g156_0 + 0.0060715068105916675*g85_0 + -0.039963713006743028*g130_0 + 0.13379699974420936*g114_0 + -0.019351052333028706*g32_0 + 0.005465008702137699*g144_0 + -0.047333974187740532*g111_0 + 0.079483181842064113*g6_0 + 0.024625093829550172*g107_0 + -0.081553507071740444*g188_0 + 0.0079611050617073541*g68_0 + -0.027721791190571193*g122_0 + 0.0076857925987084807*g72_0 + -0.015001650912389398*g146_0 + 0.0031624180291228549*g70_0 + 0.00091424116236220939*g151_0 + -0.004897505464228403*g184_0 + 0.029411193596562916*g129_0) + (-0.0113890661932595*g49_0 + 0.43994526634395975*g186_0 + 0.032893556465698831*g37_0 + -0.0067724482884122745*g139_0 + -0.0080917868401479513*g143_0 + 0.035130079845696931*g142_0 + 0.041088261442626686*g23_0 + -0.071711578038749599*g200_0 + 0.24773920028707436*g56_0 + 0.042346040556652358*g3_0 + 0.059409432474751778*g93_0 + 0.054548241925409434*g8_0 + -0.017696496838687587*g104_0 + -0.13834082855651425*g113_0 + -0.0085402629686534837*g79_0 + 0.026346481976004161*g196_0 + -0.05537557264667315*g96_0 + 0.085221500727047303*g136_0 + -0.012153052980571554*g74_0 + -0.025582168623119725*g2_0 + -0.023765524883918303*g185_0 + -0.023113646418614731*g180_0 + -0.075707551392193928*g164_0 + -0.018746841788203357*g31_0 + -0.009815448164423108*g190_0 + 0.026572448446895242*g86_0 + -0.011395666445370449*g175_0 + -0.0016147882988804348*g145_0 + 0.0045373509168388313*g174_0 + -0.0094281232021259358*g76_0 + -0.015997831746262965*g87_0 + -0.004025214403473097*g102_0 + 0.01531205020383126*g138_0); const v8d a1 = (0.2731287727919155*g_one_1 + -0.081199031955779918*g187_1 + 0.11813626380632239*g9_1 + 0.0076039093569542924*g105_1 + -0.026057686172391653*g25_1 + 0.093899656612461566*g55_1 + -0.0022953587452464474*g157_1 + -0.012054719324202486*g95_1 + -0.025239038291381324*g94_1 + 0.058722930685422406*g34_1 + -0.051901881701030154*g166_1 + 0.006868410804076938*g19_1 + -0.015795470194206913*g181_1 + -0.30214112927973891*g54_1 + -0.023431513721749425*g110_1 + 0.014413770133822454*g156_1 + 0.0060715068105916675*g85_1 + -0.039963713006743028*g130_1 + 0.13379699974420936*g114_1 + -0.019351052333028706*g32_1 + 0.005465008702137699*g144_1 + -0.047333974187740532*g111_1 + 0.079483181842064113*g6_1 + 0.024625093829550172*g107_1 + -0.081553507071740444*g188_1 + 0.0079611050617073541*g68_1 + -0.027721791190571193*g122_1 + 0.0076857925987084807*g72_1 + -0.015001650912389398*g146_1 + 0.0031624180291228549*g70_1 + 0.00091424116236220939*g151_1 + -0.004897505464228403*g184_1 + 0.029411193596562916*g129_1) + (-0.0113890661932595*g49_1 + 0.43994526634395975*g186_1 + 0.032893556465698831*g37_1 + -0.0067724482884122745*g139_1 + -0.0080917868401479513*g143_1 + 0.035130079845696931*g142_1 + 0.041088261442626686*g23_1 + -0.071711578038749599*g200_1 + 0.24773920028707436*g56_1 + 0.042346040556652358*g3_1 + 0.059409432474751778*g93_1 + 0.054548241925409434*g8_1 + -0.017696496838687587*g104_1 + -0.13834082855651425*g113_1 + -0.0085402629686534837*g79_1 + 0.026346481976004161*g196_1 + -0.05537557264667315*g96_1 + 0.085221500727047303*g136_1 + -0.012153052980571554*g74_1 + -0.025582168623119725*g2_1 + -0.023765524883918303*g185_1 + -0.023113646418614731*g180_1 + -0.075707551392193928*g164_1 + -0.018746841788203357*g31_1 + -0.009815448164423108*g190_1 + 0.026572448446895242*g86_1 + -0.011395666445370449*g175_1 + -0.0016147882988804348*g145_1 + 0.0045373509168388313*g174_1 + -0.0094281232021259358*g76_1 + -0.015997831746262965*g87_1 + -0.004025214403473097*g102_1 + 0.01531205020383126*g138_1);
    std::memcpy(moment_arm + 990, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 996, &a1, 5 * sizeof(double)); L[90] = a0[6]; }
  { const v8d a0 = (0.2796402428591151*g_one_0 + -0.0012570481385565072*g187_0 + 0.055843082732947739*g37_0 + 0.03960123084974488*g23_0 + -0.016089161362641068*g166_0 + 0.0022979898236601421*g143_0 + -0.10122738784617201*g132_0 + -0.01160182508988458*g117_0 + 0.18381699654778222*g205_0 + 0.017155580926512221*g134_0 + -0.0049841127596906079*g112_0 + -0.075473136042009517*g40_0 + 0.022412750348335276*g177_0 + 0.057913998296523467*g150_0 + -0.20296493187655582*g204_0 + -0.15420759274302467*g55_0 + -0.070726512381587031*g29_0 + -0.0028942785471617982*g196_0 + 0.07763177923135138*g47_0 + 0.018257630666199003*g26_0 + 0.050411658255945978*g111_0 + 0.0087886801771036027*g155_0 + 0.010171378843937552*g129_0 + -0.025273372520615546*g148_0) + (0.17279966462868829*g9_0 + 0.14762261140460903*g186_0 + -0.021426868439524422*g139_0 + -0.016278447409964075*g2_0 + 0.063557957368615359*g199_0 + -0.020933753953786605*g157_0 + -0.012728756434967514*g209_0 + -0.29159430272380515*g54_0 + 0.035293290311060009*g3_0 + -0.050006062338883814*g92_0 + -0.0051075949778505705*g19_0 + -0.011215641507089374*g168_0 + -0.0049159394145357601*g74_0 + -0.012932015183194001*g76_0 + -0.024572411816828683*g35_0 + -0.3582831434992565*g183_0 + 0.0091175130633890135*g103_0 + -0.045277916598430161*g87_0 + -0.011297747262140875*g145_0 + -0.024710836490826438*g122_0 + 0.038865013744778278*g56_0 + 0.044955362477486674*g93_0 + 0.025398592701463042*g42_0); const v8d a1 = (0.2796402428591151*g_one_1 + -0.0012570481385565072*g187_1 + 0.055843082732947739*g37_1 + 0.03960123084974488*g23_1 + -0.016089161362641068*g166_1 + 0.0022979898236601421*g143_1 + -0.10122738784617201*g132_1 + -0.01160182508988458*g117_1 + 0.18381699654778222*g205_1 + 0.017155580926512221*g134_1 + -0.0049841127596906079*g112_1 + -0.075473136042009517*g40_1 + 0.022412750348335276*g177_1 + 0.057913998296523467*g150_1 + -0.20296493187655582*g204_1 + -0.15420759274302467*g55_1 + -0.070726512381587031*g29_1 + -0.0028942785471617982*g196_1 + 0.07763177923135138*g47_1 + 0.018257630666199003*g26_1 + 0.050411658255945978*g111_1 + 0.0087886801771036027*g155_1 + 0.010171378843937552*g129_1 + -0.025273372520615546*g148_1) + (0.17279966462868829*g9_1 + 0.14762261140460903*g186_1 + -0.021426868439524422*g139_1 + -0.016278447409964075*g2_1 + 0.063557957368615359*g199_1 + -0.020933753953786605*g157_1 + -0.012728756434967514*g209_1 + -0.29159430272380515*g54_1 + 0.035293290311060009*g3_1 + -0.050006062338883814*g92_1 + -0.0051075949778505705*g19_1 + -0.011215641507089374*g168_1 + -0.0049159394145357601*g74_1 + -0.012932015183194001*g76_1 + -0.024572411816828683*g35_1 + -0.3582831434992565*g183_1 + 0.0091175130633890135*g103_1 + -0.045277916598430161*g87_1 + -0.011297747262140875*g145_1 + -0.024710836490826438*g122_1 + 0.038865013744778278*g56_1 + 0.044955362477486674*g93_1 + 0.025398592701463042*g42_1);
    std::memcpy(moment_arm + 1001, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1007, &a1, 5 * sizeof(double)); L[91] = a0[6]; }
  { const v8d a0 = (0.30395652187608385*g_one_0 + -0.028271714256390766*g186_0 + 0.064511516318140116*g37_0 + 0.062810170397935419*g167_0 + -0.0064175009525509197*g18_0 + 0.0235925727990813*g23_0 + 0.034665639403068792*g42_0 + 0.020398712354251832*g111_0 + -0.0067474534926243888*g203_0 + 0.011823968587351522*g181_0 + -0.016904304372680073*g143_0 + -0.17758306495977716*g154_0 + -0.30391669542327709*g183_0 + 0.0020053276961672956*g114_0 + -0.06116032659325011*g48_0 + -0.009356363146716732*g76_0 + 0.09792448049782318*g98_0 + 0.019806048739635981*g189_0 + -0.10709296216763906*g172_0 + -0.010829083861307926*g120_0 + -0.032174247868459016*g87_0 + 0.0044649038916698483*g82_0 + 0.041165273802396138*g26_0 + -0.077335978125669447*g202_0 + -0.0069151129132279639*g145_0 + 0.021178803760854049*g80_0) + (0.202198101264184*g9_0 + -0.10537163450010879*g159_0 + -0.23554919547757658*g55_0 + -0.028161595868732927*g157_0 + -0.01075123726950385*g152_0 + 0.03582293186232214*g3_0 + -0.0052595367112129587*g174_0 + -0.034519193218294872*g16_0 + -0.011571107886046924*g104_0 + 0.016259664376669213*g68_0 + 0.042438435449287687*g171_0 + -0.034372277260405475*g50_0 + 0.050123317433283986*g33_0 + -0.012962082873108889*g125_0 + 0.021425837040600811*g113_0 + 0.031657492393490444*g93_0 + -0.018774533514456061*g139_0 + 0.014293660800032767*g103_0 + -0.011860094723366382*g92_0 + 0.059767276583390275*g150_0 + -0.022384519080230533*g122_0 + 0.016771963396370174*g10_0 + 0.0087077071857515394*g124_0 + 0.01123074078082918*g161_0 + -0.012992312450826307*g81_0); const v8d a1 = (0.30395652187608385*g_one_1 + -0.028271714256390766*g186_1 + 0.064511516318140116*g37_1 + 0.062810170397935419*g167_1 + -0.0064175009525509197*g18_1 + 0.0235925727990813*g23_1 + 0.034665639403068792*g42_1 + 0.020398712354251832*g111_1 + -0.0067474534926243888*g203_1 + 0.011823968587351522*g181_1 + -0.016904304372680073*g143_1 + -0.17758306495977716*g154_1 + -0.30391669542327709*g183_1 + 0.0020053276961672956*g114_1 + -0.06116032659325011*g48_1 + -0.009356363146716732*g76_1 + 0.09792448049782318*g98_1 + 0.019806048739635981*g189_1 + -0.10709296216763906*g172_1 + -0.010829083861307926*g120_1 + -0.032174247868459016*g87_1 + 0.0044649038916698483*g82_1 + 0.041165273802396138*g26_1 + -0.077335978125669447*g202_1 + -0.0069151129132279639*g145_1 + 0.021178803760854049*g80_1) + (0.202198101264184*g9_1 + -0.10537163450010879*g159_1 + -0.23554919547757658*g55_1 + -0.028161595868732927*g157_1 + -0.01075123726950385*g152_1 + 0.03582293186232214*g3_1 + -0.0052595367112129587*g174_1 + -0.034519193218294872*g16_1 + -0.011571107886046924*g104_1 + 0.016259664376669213*g68_1 + 0.042438435449287687*g171_1 + -0.034372277260405475*g50_1 + 0.050123317433283986*g33_1 + -0.012962082873108889*g125_1 + 0.021425837040600811*g113_1 + 0.031657492393490444*g93_1 + -0.018774533514456061*g139_1 + 0.014293660800032767*g103_1 + -0.011860094723366382*g92_1 + 0.059767276583390275*g150_1 + -0.022384519080230533*g122_1 + 0.016771963396370174*g10_1 + 0.0087077071857515394*g124_1 + 0.01123074078082918*g161_1 + -0.012992312450826307*g81_1);
    std::memcpy(moment_arm + 1012, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1018, &a1, 5 * sizeof(double)); L[92] = a0[6]; }
  { const v8d a0 = (0.27620860692573773*g_one_0 + 0.063406788385507826*g186_0 + 0.071595158520291025*g159_0 + -0.013385642771338439*g146_0 + 0.015422765689474087*g96_0 + 0.012265889376055078*g80_0 + 0.021223325652210003*g97_0 + -0.027963476248007005*g157_0 + -0.032285117542839248*g106_0 + -0.0047220902802330277*g4_0 + 0.064250500223675552*g10_0 + -0.017390190630228279*g172_0 + -0.022299507351851901*g36_0 + 0.018062558338378391*g138_0 + -0.043087343366128412*g193_0 + -0.0095164537846628029*g76_0 + 0.014757197701053588*g170_0 + -0.017832169904489416*g87_0) + (0.19385450804319992*g9_0 + 0.048183557933785016*g37_0 + 0.046772061742531797*g17_0 + -0.007945188266714226*g2_0 + -0.0084685288623811833*g102_0 + -0.0093615437925340921*g196_0 + -0.016223010292453734*g69_0 + 0.026770076883644401*g42_0 + 0.019494039516933202*g77_0 + 0.039713744598666653*g94_0 + 0.090866637354175508*g33_0 + 0.0026306358999285224*g184_0 + -0.022990421077214693*g139_0 + -0.019721552402410716*g164_0 + -0.040789578174105452*g205_0 + -0.029245403356289966*g197_0 + -0.0051335089396798272*g180_0 + 0.057443466915362257*g26_0); const v8d a1 = (0.27620860692573773*g_one_1 + 0.063406788385507826*g186_1 + 0.071595158520291025*g159_1 + -0.013385642771338439*g146_1 + 0.015422765689474087*g96_1 + 0.012265889376055078*g80_1 + 0.021223325652210003*g97_1 + -0.027963476248007005*g157_1 + -0.032285117542839248*g106_1 + -0.0047220902802330277*g4_1 + 0.064250500223675552*g10_1 + -0.017390190630228279*g172_1 + -0.022299507351851901*g36_1 + 0.018062558338378391*g138_1 + -0.043087343366128412*g193_1 + -0.0095164537846628029*g76_1 + 0.014757197701053588*g170_1 + -0.017832169904489416*g87_1) + (0.19385450804319992*g9_1 + 0.048183557933785016*g37_1 + 0.046772061742531797*g17_1 + -0.007945188266714226*g2_1 + -0.0084685288623811833*g102_1 + -0.0093615437925340921*g196_1 + -0.016223010292453734*g69_1 + 0.026770076883644401*g42_1 + 0.019494039516933202*g77_1 + 0.039713744598666653*g94_1 + 0.090866637354175508*g33_1 + 0.0026306358999285224*g184_1 + -0.022990421077214693*g139_1 + -0.019721552402410716*g164_1 + -0.040789578174105452*g205_1 + -0.029245403356289966*g197_1 + -0.0051335089396798272*g180_1 + 0.057443466915362257*g26_1);
    std::memcpy(moment_arm + 1023, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1029, &a1, 5 * sizeof(double)); L[93] = a0[6]; }
  { const v8d a0 = (0.24219060582604793*g_one_0 + -0.052432824764816123*g186_0 + -0.031585915692455842*g159_0 + -0.034835485342492832*g149_0 + 0.0022414635699944587*g2_0 + -0.011823474887542906*g69_0 + 0.025316688252994272*g97_0 + -0.026539750912634216*g92_0 + -0.0089442463587479839*g78_0 + -0.082051487507168425*g182_0 + -0.012836546251227552*g76_0 + -0.030760211008073472*g36_0 + -0.04531458837273783*g44_0 + 0.0043634331696774204*g39_0 + 0.0783134373585605*g154_0 + 0.052913825877230633*g10_0 + -0.090924365704392246*g151_0 + 0.048470153181710697*g5_0 + -0.012700025999127198*g96_0 + 0.009503968884490243*g179_0 + -0.013133453382654999*g195_0) + (0.2653185635724134*g9_0 + 0.085600857632261579*g37_0 + 0.038161736474509891*g17_0 + 0.0063332106516324083*g202_0 + 0.033085999463018718*g111_0 + 0.029770772189912333*g80_0 + -0.05513572591786816*g157_0 + 0.011891798643331605*g184_0 + -0.017695483664630068*g16_0 + -0.022921893675559139*g162_0 + 0.020640922997045751*g49_0 + 0.0054773310875742987*g68_0 + 0.029547168904811707*g138_0 + 0.00098971963567591123*g23_0 + 0.01909100669744845*g102_0 + 0.035078265561216578*g59_0 + 0.23529727526509372*g47_0 + -0.040460159555892779*g193_0 + -0.0299650602208828*g122_0 + -0.026570348339248439*g116_0); const v8d a1 = (0.24219060582604793*g_one_1 + -0.052432824764816123*g186_1 + -0.031585915692455842*g159_1 + -0.034835485342492832*g149_1 + 0.0022414635699944587*g2_1 + -0.011823474887542906*g69_1 + 0.025316688252994272*g97_1 + -0.026539750912634216*g92_1 + -0.0089442463587479839*g78_1 + -0.082051487507168425*g182_1 + -0.012836546251227552*g76_1 + -0.030760211008073472*g36_1 + -0.04531458837273783*g44_1 + 0.0043634331696774204*g39_1 + 0.0783134373585605*g154_1 + 0.052913825877230633*g10_1 + -0.090924365704392246*g151_1 + 0.048470153181710697*g5_1 + -0.012700025999127198*g96_1 + 0.009503968884490243*g179_1 + -0.013133453382654999*g195_1) + (0.2653185635724134*g9_1 + 0.085600857632261579*g37_1 + 0.038161736474509891*g17_1 + 0.0063332106516324083*g202_1 + 0.033085999463018718*g111_1 + 0.029770772189912333*g80_1 + -0.05513572591786816*g157_1 + 0.011891798643331605*g184_1 + -0.017695483664630068*g16_1 + -0.022921893675559139*g162_1 + 0.020640922997045751*g49_1 + 0.0054773310875742987*g68_1 + 0.029547168904811707*g138_1 + 0.00098971963567591123*g23_1 + 0.01909100669744845*g102_1 + 0.035078265561216578*g59_1 + 0.23529727526509372*g47_1 + -0.040460159555892779*g193_1 + -0.0299650602208828*g122_1 + -0.026570348339248439*g116_1);
    std::memcpy(moment_arm + 1034, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1040, &a1, 5 * sizeof(double)); L[94] = a0[6]; }
  { const v8d a0 = (0.14601456923143266*g_one_0 + 0.079115525887205024*g159_0 + -0.023956078408306661*g4_0 + 0.034867172119531054*g142_0 + -0.23346290606940329*g99_0 + 0.036738236885538206*g184_0 + -0.026153625737432587*g2_0 + -0.074391725371324144*g33_0 + 0.019194255222691799*g17_0 + -0.015414810143440452*g93_0 + -0.029029097111676335*g31_0 + -0.052450402382795885*g106_0 + 0.072243865699440163*g37_0 + 0.087282521172204544*g107_0 + -0.013249581723086105*g88_0 + -0.02785987713682618*g90_0 + 0.023539014454012061*g86_0 + 0.030585967822532718*g72_0 + -0.036684184190651885*g19_0 + -0.16233726576020935*g170_0 + 0.023867072697335529*g42_0 + 0.040315373225881863*g3_0 + 0.05504641072851485*g134_0 + 0.0019066414323173297*g32_0 + -0.0077412321846331662*g176_0 + 0.011714362461474349*g121_0 + -0.063176804276280113*g182_0 + 0.0090419151505478565*g89_0 + -0.016456014673034217*g71_0 + 0.0036772664491863398*g68_0 + 0.0069054603828256128*g6_0) + (0.18836770849686629*g9_0 + -0.011293368241020629*g52_0 + -0.033143569849378517*g139_0 + 0.0026163099781229232*g196_0 + 0.0757258714813481*g209_0 + -0.0070005578504013328*g69_0 + -0.0091420152358246895*g78_0 + 0.052533452492115308*g80_0 + -0.20988453607157609*g29_0 + 0.11887109736216886*g59_0 + -0.1403132469288218*g132_0 + -0.021113661524781214*g104_0 + -0.0075061195220540947*g137_0 + 0.060401296998220305*g126_0 + -0.1303214122552554*g41_0 + 0.0071381909866654403*g15_0 + -0.038029754634462606*g108_0 + -0.018256412914996294*g147_0 + -0.040097157351797669*g173_0 + -0.1555093126460195*g136_0 + 0.023169449233418633*g95_0 + 0.04519347550166096*g163_0 + -0.020800326507805143*g122_0 + -0.010390417092895992*g185_0 + -0.072960510177422444*g50_0 + -0.070444368742158703*g199_0 + -0.067251447609441767*g153_0 + -0.0032992284049202262*g146_0 + 0.014034692612735282*g18_0 + 0.03062124421192201*g191_0); const v8d a1 = (0.14601456923143266*g_one_1 + 0.079115525887205024*g159_1 + -0.023956078408306661*g4_1 + 0.034867172119531054*g142_1 + -0.23346290606940329*g99_1 + 0.036738236885538206*g184_1 + -0.026153625737432587*g2_1 + -0.074391725371324144*g33_1 + 0.019194255222691799*g17_1 + -0.015414810143440452*g93_1 + -0.029029097111676335*g31_1 + -0.052450402382795885*g106_1 + 0.072243865699440163*g37_1 + 0.087282521172204544*g107_1 + -0.013249581723086105*g88_1 + -0.02785987713682618*g90_1 + 0.023539014454012061*g86_1 + 0.030585967822532718*g72_1 + -0.036684184190651885*g19_1 + -0.16233726576020935*g170_1 + 0.023867072697335529*g42_1 + 0.040315373225881863*g3_1 + 0.05504641072851485*g134_1 + 0.0019066414323173297*g32_1 + -0.0077412321846331662*g176_1 + 0.011714362461474349*g121_1 + -0.063176804276280113*g182_1 + 0.0090419151505478565*g89_1 + -0.016456014673034217*g71_1 + 0.0036772664491863398*g68_1 + 0.0069054603828256128*g6_1) + (0.18836770849686629*g9_1 + -0.011293368241020629*g52_1 + -0.033143569849378517*g139_1 + 0.0026163099781229232*g196_1 + 0.0757258714813481*g209_1 + -0.0070005578504013328*g69_1 + -0.0091420152358246895*g78_1 + 0.052533452492115308*g80_1 + -0.20988453607157609*g29_1 + 0.11887109736216886*g59_1 + -0.1403132469288218*g132_1 + -0.021113661524781214*g104_1 + -0.0075061195220540947*g137_1 + 0.060401296998220305*g126_1 + -0.1303214122552554*g41_1 + 0.0071381909866654403*g15_1 + -0.038029754634462606*g108_1 + -0.018256412914996294*g147_1 + -0.040097157351797669*g173_1 + -0.1555093126460195*g136_1 + 0.023169449233418633*g95_1 + 0.04519347550166096*g163_1 + -0.020800326507805143*g122_1 + -0.010390417092895992*g185_1 + -0.072960510177422444*g50_1 + -0.070444368742158703*g199_1 + -0.067251447609441767*g153_1 + -0.0032992284049202262*g146_1 + 0.014034692612735282*g18_1 + 0.03062124421192201*g191_1);
    std::memcpy(moment_arm + 1045, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1051, &a1, 5 * sizeof(double)); L[95] = a0[6]; }
  { const v8d a0 = (0.17994016181350106*g_one_0 + -0.023992952740177338*g34_0 + 0.015496531384637356*g44_0 + -0.020749412018329604*g122_0 + -0.0046247741972549944*g204_0 + -0.024285592621381493*g2_0 + -0.056651674220243836*g83_0 + 0.15153136833716011*g29_0 + -0.011298614477625712*g76_0 + -0.086653327148156364*g98_0 + 0.00032529831683279309*g23_0 + 0.10610169042039622*g3_0 + 0.13442762295479602*g9_0 + 0.013517035939969552*g30_0 + 0.013074577546688568*g112_0 + -0.04264331053850292*g19_0 + 0.018089483994361184*g103_0 + 0.14622242186226872*g109_0 + 0.070858790890419007*g99_0 + -0.0043476602664337359*g133_0 + 0.025849067056443593*g124_0 + 0.11923610542406884*g135_0 + -0.0083659519296647548*g101_0 + -0.0093120144193305273*g123_0 + 0.035441110936422722*g134_0 + 0.0053249247404146653*g73_0 + -0.02628626407582001*g90_0 + -0.088875455467244041*g108_0 + -0.012666455890159897*g79_0 + 0.0059126973346906083*g70_0 + 0.0036509202407777309*g68_0 + -0.0063506596991449336*g117_0 + -0.008983313159935908*g151_0 + 0.16344131226809588*g6_0 + -0.036073908727086483*g87_0) + (0.013656443973206008*g58_0 + -0.023420974198208686*g4_0 + -0.0023676046696728373*g156_0 + 0.0078263761677312277*g196_0 + -0.10710714495434705*g132_0 + 0.05645512212290462*g80_0 + -0.013515946730245693*g168_0 + -0.0093757007849253546*g173_0 + 0.0055863121430925885*g52_0 + -0.0011257253338203637*g116_0 + -0.0063766254308008355*g148_0 + -0.02778926055644523*g104_0 + -0.050379785173415077*g10_0 + -0.026143934724183537*g140_0 + 0.028258127136514363*g72_0 + -0.013376494122059445*g145_0 + -0.053534637181054508*g82_0 + -0.071628769178959772*g141_0 + -0.099853431362382589*g31_0 + -0.010851184914349107*g160_0 + 0.030889251392759502*g37_0 + -0.0071363500126934692*g163_0 + 0.0035638578318038868*g121_0 + -0.018256109910239349*g17_0 + -0.015385392569669865*g71_0 + -0.010083872438246004*g125_0 + -0.003985349189267789*g74_0 + -0.013717526150620765*g42_0 + 0.0012090766946849195*g66_0 + 0.026137947429250425*g102_0 + -0.0028344923977737416*g69_0 + 0.0034046805996975505*g89_0 + -0.029898861405564772*g154_0 + -0.066283328790665216*g96_0); const v8d a1 = (0.17994016181350106*g_one_1 + -0.023992952740177338*g34_1 + 0.015496531384637356*g44_1 + -0.020749412018329604*g122_1 + -0.0046247741972549944*g204_1 + -0.024285592621381493*g2_1 + -0.056651674220243836*g83_1 + 0.15153136833716011*g29_1 + -0.011298614477625712*g76_1 + -0.086653327148156364*g98_1 + 0.00032529831683279309*g23_1 + 0.10610169042039622*g3_1 + 0.13442762295479602*g9_1 + 0.013517035939969552*g30_1 + 0.013074577546688568*g112_1 + -0.04264331053850292*g19_1 + 0.018089483994361184*g103_1 + 0.14622242186226872*g109_1 + 0.070858790890419007*g99_1 + -0.0043476602664337359*g133_1 + 0.025849067056443593*g124_1 + 0.11923610542406884*g135_1 + -0.0083659519296647548*g101_1 + -0.0093120144193305273*g123_1 + 0.035441110936422722*g134_1 + 0.0053249247404146653*g73_1 + -0.02628626407582001*g90_1 + -0.088875455467244041*g108_1 + -0.012666455890159897*g79_1 + 0.0059126973346906083*g70_1 + 0.0036509202407777309*g68_1 + -0.0063506596991449336*g117_1 + -0.008983313159935908*g151_1 + 0.16344131226809588*g6_1 + -0.036073908727086483*g87_1) + (0.013656443973206008*g58_1 + -0.023420974198208686*g4_1 + -0.0023676046696728373*g156_1 + 0.0078263761677312277*g196_1 + -0.10710714495434705*g132_1 + 0.05645512212290462*g80_1 + -0.013515946730245693*g168_1 + -0.0093757007849253546*g173_1 + 0.0055863121430925885*g52_1 + -0.0011257253338203637*g116_1 + -0.0063766254308008355*g148_1 + -0.02778926055644523*g104_1 + -0.050379785173415077*g10_1 + -0.026143934724183537*g140_1 + 0.028258127136514363*g72_1 + -0.013376494122059445*g145_1 + -0.053534637181054508*g82_1 + -0.071628769178959772*g141_1 + -0.099853431362382589*g31_1 + -0.010851184914349107*g160_1 + 0.030889251392759502*g37_1 + -0.0071363500126934692*g163_1 + 0.0035638578318038868*g121_1 + -0.018256109910239349*g17_1 + -0.015385392569669865*g71_1 + -0.010083872438246004*g125_1 + -0.003985349189267789*g74_1 + -0.013717526150620765*g42_1 + 0.0012090766946849195*g66_1 + 0.026137947429250425*g102_1 + -0.0028344923977737416*g69_1 + 0.0034046805996975505*g89_1 + -0.029898861405564772*g154_1 + -0.066283328790665216*g96_1);
    std::memcpy(moment_arm + 1056, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1062, &a1, 5 * sizeof(double)); L[96] = a0[6]; }
  { const v8d a0 = (0.24174429537700906*g_one_0 + 0.42283308919197488*g34_0 + 0.0063337820879816251*g44_0 + -0.019002345588776146*g4_0 + 0.11577574472501596*g6_0 + -0.025697263696629471*g168_0 + -0.019074928392017281*g2_0 + -0.24975937084009317*g26_0 + -0.11552619605514816*g119_0 + 0.065951806931358825*g202_0 + -0.16503147294504367*g96_0 + -0.018337154194779364*g108_0 + 0.035737846748818969*g50_0 + -0.038566144046068236*g195_0 + 0.0033925199619415465*g83_0 + -0.046051156211651879*g19_0 + 0.10268361471176816*g99_0 + -0.013786665814857324*g5_0 + -0.092885219470231054*g92_0 + -0.025762649040220735*g10_0 + 0.048625702997554088*g37_0 + 0.13952780077758056*g113_0) + (-0.028737643468219557*g58_0 + -0.047173837732788645*g104_0 + -0.066462291342030994*g178_0 + -0.006649504055842392*g156_0 + -0.016607512850667212*g122_0 + 0.015708085785408367*g78_0 + -0.13308772245974337*g192_0 + -0.015365748635536469*g173_0 + 0.03234029600444515*g80_0 + -0.028681066242512099*g106_0 + 0.092346376100358785*g111_0 + 0.51855727818156949*g114_0 + 0.014765250612122255*g70_0 + 0.039477162567047627*g72_0 + -0.032920725730033906*g127_0 + -0.011601349391057067*g74_0 + 0.047762523534113747*g186_0 + 0.018135056306955211*g105_0 + 0.093345139571720567*g9_0 + -0.032551057838254002*g132_0 + -0.027065268970761166*g41_0); const v8d a1 = (0.24174429537700906*g_one_1 + 0.42283308919197488*g34_1 + 0.0063337820879816251*g44_1 + -0.019002345588776146*g4_1 + 0.11577574472501596*g6_1 + -0.025697263696629471*g168_1 + -0.019074928392017281*g2_1 + -0.24975937084009317*g26_1 + -0.11552619605514816*g119_1 + 0.065951806931358825*g202_1 + -0.16503147294504367*g96_1 + -0.018337154194779364*g108_1 + 0.035737846748818969*g50_1 + -0.038566144046068236*g195_1 + 0.0033925199619415465*g83_1 + -0.046051156211651879*g19_1 + 0.10268361471176816*g99_1 + -0.013786665814857324*g5_1 + -0.092885219470231054*g92_1 + -0.025762649040220735*g10_1 + 0.048625702997554088*g37_1 + 0.13952780077758056*g113_1) + (-0.028737643468219557*g58_1 + -0.047173837732788645*g104_1 + -0.066462291342030994*g178_1 + -0.006649504055842392*g156_1 + -0.016607512850667212*g122_1 + 0.015708085785408367*g78_1 + -0.13308772245974337*g192_1 + -0.015365748635536469*g173_1 + 0.03234029600444515*g80_1 + -0.028681066242512099*g106_1 + 0.092346376100358785*g111_1 + 0.51855727818156949*g114_1 + 0.014765250612122255*g70_1 + 0.039477162567047627*g72_1 + -0.032920725730033906*g127_1 + -0.011601349391057067*g74_1 + 0.047762523534113747*g186_1 + 0.018135056306955211*g105_1 + 0.093345139571720567*g9_1 + -0.032551057838254002*g132_1 + -0.027065268970761166*g41_1);
    std::memcpy(moment_arm + 1067, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1073, &a1, 5 * sizeof(double)); L[97] = a0[6]; }
  { const v8d a0 = (0.15257040875099254*g_one_0 + 0.0050207759946544351*g58_0 + 0.069420878874780892*g109_0 + -0.039442974564148373*g17_0 + 0.10992297893428619*g9_0 + 0.026808939552005806*g102_0 + -0.033702241338155733*g2_0 + -0.10364540981383667*g128_0 + -0.048799443115387302*g19_0 + -0.041074473467859383*g106_0 + 0.0073369998538940703*g100_0 + -0.066410804165348197*g118_0 + 0.0061066098961145461*g103_0 + 0.0064790486420249985*g129_0 + -0.026648222145408271*g108_0 + -0.0062544319261048685*g74_0 + 0.0082300897721680269*g75_0 + -0.00043343255759417562*g130_0 + -0.034436647353992281*g170_0 + 0.0083705001037077953*g196_0 + 0.016522267558987013*g86_0 + -0.012214754924332655*g38_0 + 0.0063105350020231897*g70_0 + 0.0014167721181326043*g68_0 + 0.052886744431198798*g26_0 + -0.021901232094052467*g90_0 + -0.0056741417339963417*g101_0 + 0.01633106636083179*g16_0 + 0.016998277277929463*g18_0 + 0.10794507011667925*g119_0 + 0.029607789789942565*g134_0) + (-0.055610320056415426*g34_0 + -0.025355689692736192*g104_0 + -0.010006516663471051*g4_0 + 0.081333316608493009*g107_0 + -0.041457846637544017*g10_0 + -0.057608326019868997*g29_0 + -0.014055988493542521*g139_0 + 0.10421989094855261*g3_0 + -0.056714879117772385*g116_0 + 0.029226422742109133*g72_0 + -0.089512300827182201*g171_0 + 0.032393691774574462*g80_0 + -0.020692504632635424*g127_0 + -0.0048724987851037852*g88_0 + -0.0022747083695659944*g69_0 + 0.021122691892437123*g105_0 + -0.065188078449031281*g169_0 + -0.08351428491692639*g154_0 + 0.00030025172546867089*g132_0 + -0.057495746265321702*g141_0 + 0.01777459324105387*g124_0 + -0.027632823177005848*g20_0 + -0.0056024879879413274*g123_0 + -0.036378086200528403*g87_0 + -0.014558098913227048*g25_0 + 0.023133810487226656*g112_0 + -0.018177338023593798*g71_0 + 0.097402373913207468*g113_0 + 0.011109631015569348*g21_0 + 0.042945786777869324*g40_0 + 0.0078747680160760111*g24_0); const v8d a1 = (0.15257040875099254*g_one_1 + 0.0050207759946544351*g58_1 + 0.069420878874780892*g109_1 + -0.039442974564148373*g17_1 + 0.10992297893428619*g9_1 + 0.026808939552005806*g102_1 + -0.033702241338155733*g2_1 + -0.10364540981383667*g128_1 + -0.048799443115387302*g19_1 + -0.041074473467859383*g106_1 + 0.0073369998538940703*g100_1 + -0.066410804165348197*g118_1 + 0.0061066098961145461*g103_1 + 0.0064790486420249985*g129_1 + -0.026648222145408271*g108_1 + -0.0062544319261048685*g74_1 + 0.0082300897721680269*g75_1 + -0.00043343255759417562*g130_1 + -0.034436647353992281*g170_1 + 0.0083705001037077953*g196_1 + 0.016522267558987013*g86_1 + -0.012214754924332655*g38_1 + 0.0063105350020231897*g70_1 + 0.0014167721181326043*g68_1 + 0.052886744431198798*g26_1 + -0.021901232094052467*g90_1 + -0.0056741417339963417*g101_1 + 0.01633106636083179*g16_1 + 0.016998277277929463*g18_1 + 0.10794507011667925*g119_1 + 0.029607789789942565*g134_1) + (-0.055610320056415426*g34_1 + -0.025355689692736192*g104_1 + -0.010006516663471051*g4_1 + 0.081333316608493009*g107_1 + -0.041457846637544017*g10_1 + -0.057608326019868997*g29_1 + -0.014055988493542521*g139_1 + 0.10421989094855261*g3_1 + -0.056714879117772385*g116_1 + 0.029226422742109133*g72_1 + -0.089512300827182201*g171_1 + 0.032393691774574462*g80_1 + -0.020692504632635424*g127_1 + -0.0048724987851037852*g88_1 + -0.0022747083695659944*g69_1 + 0.021122691892437123*g105_1 + -0.065188078449031281*g169_1 + -0.08351428491692639*g154_1 + 0.00030025172546867089*g132_1 + -0.057495746265321702*g141_1 + 0.01777459324105387*g124_1 + -0.027632823177005848*g20_1 + -0.0056024879879413274*g123_1 + -0.036378086200528403*g87_1 + -0.014558098913227048*g25_1 + 0.023133810487226656*g112_1 + -0.018177338023593798*g71_1 + 0.097402373913207468*g113_1 + 0.011109631015569348*g21_1 + 0.042945786777869324*g40_1 + 0.0078747680160760111*g24_1);
    std::memcpy(moment_arm + 1078, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1084, &a1, 5 * sizeof(double)); L[98] = a0[6]; }
  { const v8d a0 = (0.18049680525055617*g_one_0 + 0.013489600999442143*g186_0 + 0.08381675419304499*g9_0 + 0.111073490360368*g114_0 + -0.076424138411718051*g158_0 + 0.071104533584786425*g3_0 + -0.046394593013229637*g116_0 + -0.021705083672907848*g106_0 + -0.0077802105674977294*g192_0 + 0.016503419812217954*g103_0 + -0.019647988271812852*g10_0 + -0.10975878848560768*g29_0 + -0.00057946193145165547*g69_0 + -0.16775360059672956*g48_0 + 0.048806341915120552*g135_0 + 0.01453383303495338*g105_0 + 0.00023163749471077403*g77_0 + -0.03126944266366985*g17_0 + 0.03529663330088819*g111_0 + 0.0071591877166897761*g70_0 + 0.0014480544783810904*g89_0 + 0.0063253963964406811*g73_0 + -0.01487740100870851*g20_0 + 0.0074567436700845252*g75_0 + 0.017248707052662897*g16_0 + -0.0031748329401496095*g101_0) + (0.060704595604010848*g119_0 + -0.015500822079231683*g4_0 + 0.10296461220490012*g160_0 + 0.044382138288688852*g84_0 + -0.028519841859619886*g2_0 + -0.038148003538666077*g19_0 + 0.0077811941238431753*g100_0 + 0.015984909925193733*g78_0 + 0.011073225809117748*g134_0 + 0.19143010074673905*g109_0 + -0.023956019634441876*g87_0 + 0.021938151035319344*g72_0 + -0.019425138563682522*g104_0 + -0.026624090350792544*g82_0 + -0.0085695277235774987*g74_0 + 0.012588140046007102*g129_0 + -0.061100667775850416*g153_0 + 0.019693576198303447*g102_0 + -0.014782272668575335*g71_0 + 0.0025365801587308246*g121_0 + 0.0064362876785005055*g83_0 + -8.2990535828784978e-05*g68_0 + -0.0085517047515565759*g141_0 + 0.013592053068658088*g86_0 + 0.014943047069925474*g95_0); const v8d a1 = (0.18049680525055617*g_one_1 + 0.013489600999442143*g186_1 + 0.08381675419304499*g9_1 + 0.111073490360368*g114_1 + -0.076424138411718051*g158_1 + 0.071104533584786425*g3_1 + -0.046394593013229637*g116_1 + -0.021705083672907848*g106_1 + -0.0077802105674977294*g192_1 + 0.016503419812217954*g103_1 + -0.019647988271812852*g10_1 + -0.10975878848560768*g29_1 + -0.00057946193145165547*g69_1 + -0.16775360059672956*g48_1 + 0.048806341915120552*g135_1 + 0.01453383303495338*g105_1 + 0.00023163749471077403*g77_1 + -0.03126944266366985*g17_1 + 0.03529663330088819*g111_1 + 0.0071591877166897761*g70_1 + 0.0014480544783810904*g89_1 + 0.0063253963964406811*g73_1 + -0.01487740100870851*g20_1 + 0.0074567436700845252*g75_1 + 0.017248707052662897*g16_1 + -0.0031748329401496095*g101_1) + (0.060704595604010848*g119_1 + -0.015500822079231683*g4_1 + 0.10296461220490012*g160_1 + 0.044382138288688852*g84_1 + -0.028519841859619886*g2_1 + -0.038148003538666077*g19_1 + 0.0077811941238431753*g100_1 + 0.015984909925193733*g78_1 + 0.011073225809117748*g134_1 + 0.19143010074673905*g109_1 + -0.023956019634441876*g87_1 + 0.021938151035319344*g72_1 + -0.019425138563682522*g104_1 + -0.026624090350792544*g82_1 + -0.0085695277235774987*g74_1 + 0.012588140046007102*g129_1 + -0.061100667775850416*g153_1 + 0.019693576198303447*g102_1 + -0.014782272668575335*g71_1 + 0.0025365801587308246*g121_1 + 0.0064362876785005055*g83_1 + -8.2990535828784978e-05*g68_1 + -0.0085517047515565759*g141_1 + 0.013592053068658088*g86_1 + 0.014943047069925474*g95_1);
    std::memcpy(moment_arm + 1089, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1095, &a1, 5 * sizeof(double)); L[99] = a0[6]; }
  { const v8d a0 = (0.18841122068323229*g_one_0 + 0.059059548690640243*g109_0 + -0.052778504579938011*g99_0 + -0.16430182052455031*g29_0 + 0.12230217174869078*g3_0 + -0.12789183337896881*g31_0 + -0.018834798330628073*g2_0 + -0.023755464880777136*g58_0 + 0.025080341883901475*g103_0 + 0.023708620638016247*g26_0 + 0.020842613763442357*g72_0 + 0.00093919910978987689*g101_0 + -0.014190619321196824*g74_0 + -0.0081695683336438403*g23_0 + -0.046212877179535303*g198_0 + 0.0087568992535404615*g59_0 + -6.281027356649307e-05*g138_0 + 0.0062916987168612033*g100_0 + 0.00637728697230063*g167_0 + 0.11519497346236582*g114_0 + 0.0039170245806938973*g106_0 + 0.0070923987862233067*g102_0) + (0.037344728981310325*g119_0 + -0.025950440879912093*g4_0 + -0.016972366329332158*g120_0 + -0.050668518476722942*g178_0 + -0.024295758856301728*g104_0 + 0.015402978428442285*g78_0 + -0.026652175378629961*g19_0 + -0.011234952877297989*g76_0 + -0.057460096138220819*g33_0 + -0.0035178111158656964*g90_0 + -0.028772872218243661*g17_0 + 0.010289706936340248*g129_0 + 0.011960187387623927*g105_0 + 0.05230914103958946*g116_0 + -0.0050670879513979106*g151_0 + -0.021773344916692246*g193_0 + -0.033271568565415514*g82_0 + -0.011853133703748442*g77_0 + -0.026135451537360913*g87_0 + 0.011998452837117176*g89_0 + 0.0031992870606720992*g68_0 + -0.010915012574183159*g71_0); const v8d a1 = (0.18841122068323229*g_one_1 + 0.059059548690640243*g109_1 + -0.052778504579938011*g99_1 + -0.16430182052455031*g29_1 + 0.12230217174869078*g3_1 + -0.12789183337896881*g31_1 + -0.018834798330628073*g2_1 + -0.023755464880777136*g58_1 + 0.025080341883901475*g103_1 + 0.023708620638016247*g26_1 + 0.020842613763442357*g72_1 + 0.00093919910978987689*g101_1 + -0.014190619321196824*g74_1 + -0.0081695683336438403*g23_1 + -0.046212877179535303*g198_1 + 0.0087568992535404615*g59_1 + -6.281027356649307e-05*g138_1 + 0.0062916987168612033*g100_1 + 0.00637728697230063*g167_1 + 0.11519497346236582*g114_1 + 0.0039170245806938973*g106_1 + 0.0070923987862233067*g102_1) + (0.037344728981310325*g119_1 + -0.025950440879912093*g4_1 + -0.016972366329332158*g120_1 + -0.050668518476722942*g178_1 + -0.024295758856301728*g104_1 + 0.015402978428442285*g78_1 + -0.026652175378629961*g19_1 + -0.011234952877297989*g76_1 + -0.057460096138220819*g33_1 + -0.0035178111158656964*g90_1 + -0.028772872218243661*g17_1 + 0.010289706936340248*g129_1 + 0.011960187387623927*g105_1 + 0.05230914103958946*g116_1 + -0.0050670879513979106*g151_1 + -0.021773344916692246*g193_1 + -0.033271568565415514*g82_1 + -0.011853133703748442*g77_1 + -0.026135451537360913*g87_1 + 0.011998452837117176*g89_1 + 0.0031992870606720992*g68_1 + -0.010915012574183159*g71_1);
    std::memcpy(moment_arm + 1100, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1106, &a1, 5 * sizeof(double)); L[100] = a0[6]; }
  { const v8d a0 = (0.16796392198023305*g_one_0 + -0.092504962068319027*g24_0 + -0.06753847966946229*g98_0 + -0.017394680709037668*g20_0 + 0.018020381481759939*g105_0 + -0.029165011512037115*g108_0 + 0.042312679137080776*g25_0 + 0.10407800142504517*g3_0 + 0.033688339369455277*g27_0 + 0.022374610897066764*g91_0 + 0.13393540104621196*g109_0 + 0.018234169738586135*g72_0 + -0.0029419707383336467*g85_0 + -0.01613177387163826*g87_0 + -0.013272990903357037*g117_0 + -0.031745328173974088*g17_0 + 0.0076833174191923434*g102_0 + 0.0056152636101077904*g67_0 + -0.012422955626197435*g30_0) + (-0.01312478848159134*g112_0 + -0.019755274088113339*g104_0 + 0.0048167584399074394*g116_0 + -0.080237719440392097*g31_0 + 0.018867062233003485*g78_0 + 0.0015449767528573429*g69_0 + -0.067863201126786496*g5_0 + -0.033617759354510543*g110_0 + -0.0081896347308790321*g90_0 + 0.064362180459651919*g99_0 + -0.038366725871125267*g19_0 + -0.015189056891249808*g74_0 + 0.030844306625454839*g114_0 + 0.051542455885392226*g6_0 + -0.013446712235568802*g88_0 + -0.029432899986955294*g92_0 + 0.004573634960326204*g75_0 + 0.0086783101510858451*g115_0); const v8d a1 = (0.16796392198023305*g_one_1 + -0.092504962068319027*g24_1 + -0.06753847966946229*g98_1 + -0.017394680709037668*g20_1 + 0.018020381481759939*g105_1 + -0.029165011512037115*g108_1 + 0.042312679137080776*g25_1 + 0.10407800142504517*g3_1 + 0.033688339369455277*g27_1 + 0.022374610897066764*g91_1 + 0.13393540104621196*g109_1 + 0.018234169738586135*g72_1 + -0.0029419707383336467*g85_1 + -0.01613177387163826*g87_1 + -0.013272990903357037*g117_1 + -0.031745328173974088*g17_1 + 0.0076833174191923434*g102_1 + 0.0056152636101077904*g67_1 + -0.012422955626197435*g30_1) + (-0.01312478848159134*g112_1 + -0.019755274088113339*g104_1 + 0.0048167584399074394*g116_1 + -0.080237719440392097*g31_1 + 0.018867062233003485*g78_1 + 0.0015449767528573429*g69_1 + -0.067863201126786496*g5_1 + -0.033617759354510543*g110_1 + -0.0081896347308790321*g90_1 + 0.064362180459651919*g99_1 + -0.038366725871125267*g19_1 + -0.015189056891249808*g74_1 + 0.030844306625454839*g114_1 + 0.051542455885392226*g6_1 + -0.013446712235568802*g88_1 + -0.029432899986955294*g92_1 + 0.004573634960326204*g75_1 + 0.0086783101510858451*g115_1);
    std::memcpy(moment_arm + 1111, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1117, &a1, 5 * sizeof(double)); L[101] = a0[6]; }
  { const v8d a0 = (0.14369296863067199*g_one_0 + -0.087662030252632514*g119_0 + -0.10270837899974075*g98_0 + -0.086433352744661227*g31_0 + -0.02114272427934745*g82_0 + 0.01084105913157892*g27_0 + 0.00064837589187964433*g76_0 + 0.070362012396834206*g3_0 + -0.018907719675527648*g19_0 + -0.0065625710378980741*g87_0 + 0.0099111748409540026*g105_0 + 0.093097073456034213*g34_0 + -0.001348938580980156*g68_0 + -0.014887855599722324*g77_0 + -0.0099498405028629368*g2_0 + 0.0061209404549315708*g103_0 + -0.011188057657962908*g74_0 + -0.0078887431701178488*g71_0 + -0.020152216161577294*g120_0 + -0.060651076311404956*g29_0) + (0.12320110788087174*g24_0 + -0.019497194292002001*g4_0 + 0.03288879457276387*g116_0 + 0.010859688366381562*g72_0 + -0.02683501418533606*g108_0 + 0.046813579138776137*g25_0 + -0.024967831526005315*g110_0 + 0.00063186020970201014*g102_0 + 0.12978192644058012*g113_0 + -0.0070981723290229389*g88_0 + -0.015037233059112238*g17_0 + 0.027249675061370802*g95_0 + 0.0056776223717824609*g70_0 + 0.24454584350014594*g94_0 + 0.0067566964736356415*g100_0 + -0.013677924878194478*g104_0 + 0.010345350590663766*g78_0 + 0.0035811159242551249*g73_0 + 0.0088718194471271127*g16_0); const v8d a1 = (0.14369296863067199*g_one_1 + -0.087662030252632514*g119_1 + -0.10270837899974075*g98_1 + -0.086433352744661227*g31_1 + -0.02114272427934745*g82_1 + 0.01084105913157892*g27_1 + 0.00064837589187964433*g76_1 + 0.070362012396834206*g3_1 + -0.018907719675527648*g19_1 + -0.0065625710378980741*g87_1 + 0.0099111748409540026*g105_1 + 0.093097073456034213*g34_1 + -0.001348938580980156*g68_1 + -0.014887855599722324*g77_1 + -0.0099498405028629368*g2_1 + 0.0061209404549315708*g103_1 + -0.011188057657962908*g74_1 + -0.0078887431701178488*g71_1 + -0.020152216161577294*g120_1 + -0.060651076311404956*g29_1) + (0.12320110788087174*g24_1 + -0.019497194292002001*g4_1 + 0.03288879457276387*g116_1 + 0.010859688366381562*g72_1 + -0.02683501418533606*g108_1 + 0.046813579138776137*g25_1 + -0.024967831526005315*g110_1 + 0.00063186020970201014*g102_1 + 0.12978192644058012*g113_1 + -0.0070981723290229389*g88_1 + -0.015037233059112238*g17_1 + 0.027249675061370802*g95_1 + 0.0056776223717824609*g70_1 + 0.24454584350014594*g94_1 + 0.0067566964736356415*g100_1 + -0.013677924878194478*g104_1 + 0.010345350590663766*g78_1 + 0.0035811159242551249*g73_1 + 0.0088718194471271127*g16_1);
    std::memcpy(moment_arm + 1122, &a0, 6 * sizeof(double)); std::memcpy(moment_arm + 1128, &a1, 5 * sizeof(double)); L[102] = a0[6]; }
  { const v8d a1 = (0.15246395416137526*g_one_1) + (0.019650088636224104*g1_1);
    std::memset(moment_arm + 1133, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1139, &a1, 5 * sizeof(double)); L[103] = a1[5]; }
  { const v8d a1 = (0.17613639181439189*g_one_1 + -0.00043991721739145294*g13_1) + (0.020354325822973557*g1_1);
    std::memset(moment_arm + 1144, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1150, &a1, 5 * sizeof(double)); L[104] = a1[5]; }
  { const v8d a1 = (0.061679654071653572*g_one_1) + (0.018439468609932109*g1_1);
    std::memset(moment_arm + 1155, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1161, &a1, 5 * sizeof(double)); L[105] = a1[5]; }
  { const v8d a1 = (0.10015256461905843*g_one_1 + -0.0023342866292106043*g13_1) + (0.021215959271638385*g1_1 + 0.00054304835850104739*g63_1);
    std::memset(moment_arm + 1166, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1172, &a1, 5 * sizeof(double)); L[106] = a1[5]; }
  { const v8d a1 = (0.14340733367042638*g_one_1 + -0.0022075829482066179*g13_1) + (0.021164917438468017*g1_1 + 0.00051429604593487355*g63_1);
    std::memset(moment_arm + 1177, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1183, &a1, 5 * sizeof(double)); L[107] = a1[5]; }
  { const v8d a1 = (0.18932377635806855*g_one_1 + -0.010946676791554942*g13_1) + (-0.011741281786572706*g1_1 + 6.5446654856674634e-05*g269_1);
    std::memset(moment_arm + 1188, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1194, &a1, 5 * sizeof(double)); L[108] = a1[5]; }
  { const v8d a1 = (0.18068971854235913*g_one_1 + -0.010197288784605168*g13_1) + (-0.012046374032580423*g1_1 + 6.479382374976114e-05*g269_1);
    std::memset(moment_arm + 1199, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1205, &a1, 5 * sizeof(double)); L[109] = a1[5]; }
  { const v8d a1 = (0.14528402172990038*g_one_1 + 0.0041156866190291434*g13_1 + 0.00059308492869950338*g238_1) + (-0.015504427162474892*g1_1 + -2.1624658717477171e-06*g308_1 + -0.0060724210605351461*g63_1);
    std::memset(moment_arm + 1210, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1216, &a1, 5 * sizeof(double)); L[110] = a1[5]; }
  { const v8d a1 = (0.14328771737412008*g_one_1 + -0.0097140182743692214*g13_1) + (-0.010902805651531499*g1_1 + 7.4015065198838516e-06*g306_1);
    std::memset(moment_arm + 1221, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1227, &a1, 5 * sizeof(double)); L[111] = a1[5]; }
  { const v8d a1 = (0.1107178969046228*g_one_1 + -0.014548795826460842*g1_1 + -0.0022344501399263572*g63_1) + (-0.00060721045724996723*g13_1 + 2.1422059417280247e-06*g308_1);
    std::memset(moment_arm + 1232, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1238, &a1, 5 * sizeof(double)); L[112] = a1[5]; }
  { const v8d a1 = (0.098126182109802632*g_one_1 + -0.0010565669989135178*g13_1 + -0.0015507804132241666*g63_1) + (-0.014253654440665123*g1_1 + 2.0690407301920543e-06*g308_1);
    std::memset(moment_arm + 1243, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1249, &a1, 5 * sizeof(double)); L[113] = a1[5]; }
  { const v8d a1 = (0.096622107341881161*g_one_1 + -0.01436884991508092*g1_1 + -0.0021029674116264966*g63_1) + (-0.0013017240422664822*g13_1 + 1.841615491766844e-06*g308_1);
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
  { const v8d a1 = (0.020274138158276955*g_one_1 + 7.3967630650754768e-06*g299_1 + 0.0043603490105709299*g11_1) + (0.012157600516321728*g0_1 + -4.8416579022964509e-07*g307_1 + -0.0015510705674651566*g60_1);
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
  { const v8d a1 = (0.23616260120418256*g_one_1) + (0.019401735488740929*g1_1);
    std::memset(moment_arm + 1430, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1436, &a1, 5 * sizeof(double)); L[130] = a1[5]; }
  { const v8d a1 = (0.19641469899809269*g_one_1) + (0.019339382182130282*g1_1);
    std::memset(moment_arm + 1441, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1447, &a1, 5 * sizeof(double)); L[131] = a1[5]; }
  { const v8d a1 = (0.19250670520261948*g_one_1) + (0.018972001703442438*g1_1);
    std::memset(moment_arm + 1452, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1458, &a1, 5 * sizeof(double)); L[132] = a1[5]; }
  { const v8d a1 = (0.01937716682349119*g_one_1 + -0.00054640570364993511*g63_1) + (0.0082495373717470198*g1_1);
    std::memset(moment_arm + 1463, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1469, &a1, 5 * sizeof(double)); L[133] = a1[5]; }
  { const v8d a1 = (0.019017026128664308*g_one_1 + -3.5587617786331501e-05*g238_1) + (0.0072493784155107793*g1_1);
    std::memset(moment_arm + 1474, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1480, &a1, 5 * sizeof(double)); L[134] = a1[5]; }
  { const v8d a1 = (0.021621350307338864*g_one_1 + 0.010453580477736302*g1_1) + (-1.4667805877390998e-07*g308_1 + -0.0027698854892570881*g13_1);
    std::memset(moment_arm + 1485, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1491, &a1, 5 * sizeof(double)); L[135] = a1[5]; }
  { const v8d a1 = (0.049690548133627478*g_one_1 + -6.211942732309942e-07*g308_1) + (0.002198639824461294*g1_1 + 0.001371314856838501*g13_1);
    std::memset(moment_arm + 1496, 0, 6 * sizeof(double)); std::memcpy(moment_arm + 1502, &a1, 5 * sizeof(double)); L[136] = a1[5]; }
  { const v8d a1 = (0.033729546777096546*g_one_1 + 1.6817473074144646e-07*g308_1 + -0.001354639752399062*g63_1) + (0.00266945539927878*g1_1 + 0.0045890735552252624*g13_1);
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
