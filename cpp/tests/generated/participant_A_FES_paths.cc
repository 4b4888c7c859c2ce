// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/participant_A_FES.json --out cpp/tests/generated`
// from the model file participant_A_FES.json (sha256 17e8e25d99f33bc075e15c19a20e3aab8e9c0b38092473af66cc730c1c346606).
// Change the model file or the generator and regenerate instead.

#include <cmath>
#include <cstring>

#include "participant_A_FES.h"

namespace armrt::generated::participant_A_FES {

// Eight doubles, one SIMD register with AVX-512 (two with AVX2): a length and its moment arms.
using v8d = double __attribute__((vector_size(64)));

void muscle_lengths(const double* q, double* L) {
  double moment_arm[84];
  muscle_paths(q, L, moment_arm);
}

void muscle_paths(const double* q, double* L, double* moment_arm) {
  const double q0 = q[0];
  const double q1 = q[1];
  const v8d g_one = {0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e0 = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const v8d e1 = {0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double p0 = q1;
  const v8d g0 = q1*g_one - e1;
  const double p1 = q0;
  const v8d g1 = q0*g_one - e0;
  const double p2 = q1*p0;
  const v8d g2 = q1*g0 - p0*e1;
  const double p3 = q1*p1;
  const v8d g3 = q1*g1 - p1*e1;
  const double p4 = q0*p1;
  const v8d g4 = q0*g1 - p1*e0;
  const double p5 = q1*p2;
  const v8d g5 = q1*g2 - p2*e1;
  const double p6 = q1*p3;
  const v8d g6 = q1*g3 - p3*e1;
  const double p7 = q0*p4;
  const v8d g7 = q0*g4 - p4*e0;
  const v8d g8 = q1*g5 - p5*e1;
  const v8d g9 = q1*g6 - p6*e1;
  const v8d g10 = q1*g7 - p7*e1;
  const v8d g11 = q0*g7 - p7*e0;
  { const v8d a = (0.35943589043957508*g_one + 0.0038545695404445454*g0) + (-0.039350572219693764*g1);
    std::memcpy(moment_arm + 0, &a, 2 * sizeof(double)); L[0] = a[2]; }
  { const v8d a = (0.33473066287360076*g_one + 0.0015576962817986635*g11) + (-0.021160884811199852*g1 + -0.01710614612749067*g4);
    std::memcpy(moment_arm + 2, &a, 2 * sizeof(double)); L[1] = a[2]; }
  { const v8d a = (0.33473066287360076*g_one + 0.0015576962817986635*g11) + (-0.021160884811199852*g1 + -0.01710614612749067*g4);
    std::memcpy(moment_arm + 4, &a, 2 * sizeof(double)); L[2] = a[2]; }
  { const v8d a = (0.28338136608271164*g_one) + (0.018303606851437355*g1);
    std::memcpy(moment_arm + 6, &a, 2 * sizeof(double)); L[3] = a[2]; }
  { const v8d a = (0.28719747442926685*g_one) + (0.018333913075011372*g1);
    std::memcpy(moment_arm + 8, &a, 2 * sizeof(double)); L[4] = a[2]; }
  { const v8d a = (0.31510939348476741*g_one) + (0.018347585403952173*g1);
    std::memcpy(moment_arm + 10, &a, 2 * sizeof(double)); L[5] = a[2]; }
  { const v8d a = (0.31090321429854784*g_one) + (0.018333298313063819*g1);
    std::memcpy(moment_arm + 12, &a, 2 * sizeof(double)); L[6] = a[2]; }
  { const v8d a = (0.14439930529052919*g_one) + (0.018495944824771921*g1);
    std::memcpy(moment_arm + 14, &a, 2 * sizeof(double)); L[7] = a[2]; }
  { const v8d a = (0.16636600881321539*g_one) + (0.018586457750819772*g1);
    std::memcpy(moment_arm + 16, &a, 2 * sizeof(double)); L[8] = a[2]; }
  { const v8d a = (0.05784840143603056*g_one) + (0.01791288105182116*g1);
    std::memcpy(moment_arm + 18, &a, 2 * sizeof(double)); L[9] = a[2]; }
  { const v8d a = (0.09401411952021374*g_one) + (0.018633170621684413*g1);
    std::memcpy(moment_arm + 20, &a, 2 * sizeof(double)); L[10] = a[2]; }
  { const v8d a = (0.13495576823678765*g_one) + (0.018639947486272394*g1);
    std::memcpy(moment_arm + 22, &a, 2 * sizeof(double)); L[11] = a[2]; }
  { const v8d a = (0.18054915365586605*g_one + -0.013490244982363779*g4) + (-0.010064018125658672*g1 + 0.00076035805702999904*g11);
    std::memcpy(moment_arm + 24, &a, 2 * sizeof(double)); L[12] = a[2]; }
  { const v8d a = (0.17185614884687686*g_one + -0.013129924628792021*g4) + (-0.010607947535131135*g1 + 0.00081655498087052872*g11);
    std::memcpy(moment_arm + 26, &a, 2 * sizeof(double)); L[13] = a[2]; }
  { const v8d a = (0.13788023815200173*g_one + -0.0072621398786317766*g4) + (-0.011003570164694533*g1 + 0.00041496150926974642*g11);
    std::memcpy(moment_arm + 28, &a, 2 * sizeof(double)); L[14] = a[2]; }
  { const v8d a = (0.13682594851170329*g_one + -0.012179475703005739*g4) + (-0.010436576094386672*g1 + 0.00068531720259456413*g11);
    std::memcpy(moment_arm + 30, &a, 2 * sizeof(double)); L[15] = a[2]; }
  { const v8d a = (0.10582993268499524*g_one + -0.013492577373902323*g1) + (-0.0049417943619925603*g4);
    std::memcpy(moment_arm + 32, &a, 2 * sizeof(double)); L[16] = a[2]; }
  { const v8d a = (0.093340573418945791*g_one + -0.0027620542580382044*g4) + (-0.015846561972244409*g1);
    std::memcpy(moment_arm + 34, &a, 2 * sizeof(double)); L[17] = a[2]; }
  { const v8d a = (0.092937201092718247*g_one + -0.01356394993162429*g1) + (-0.0053083636125351823*g4);
    std::memcpy(moment_arm + 36, &a, 2 * sizeof(double)); L[18] = a[2]; }
  { const v8d a = (0.32798783792991626*g_one + 0.0036820443339514908*g3 + 0.0019519514988018006*g11 + -0.00012142088771236638*g8) + (-0.014081506550507257*g1 + -0.0319387052103242*g4 + -0.00038655735326601442*g10 + 0.0014608349688563225*g2);
    std::memcpy(moment_arm + 38, &a, 2 * sizeof(double)); L[19] = a[2]; }
  { const v8d a = (0.31383274558971735*g_one + 0.0037104254165799123*g3 + -0.00034214544627906332*g10 + 0.0014702905374723914*g2) + (-0.030540391344434877*g4 + 0.0016782957038975472*g11 + -0.00010386587008950145*g8 + -0.0018017545046243092*g0);
    std::memcpy(moment_arm + 40, &a, 2 * sizeof(double)); L[20] = a[2]; }
  { const v8d a = (0.30135801351578945*g_one + 0.0036676425316075445*g3 + -0.00028227899507158634*g10 + 0.0006949498177318223*g5 + -5.9126560657371762e-05*g9) + (-0.023399302047159339*g4 + 0.0012285860000156692*g11 + -0.00017256119665149788*g8 + -0.0022029168221863768*g0);
    std::memcpy(moment_arm + 42, &a, 2 * sizeof(double)); L[21] = a[2]; }
  { const v8d a = (0.16748698437964138*g_one + -0.0002289055349319931*g5) + (-0.0073588586514760912*g1);
    std::memcpy(moment_arm + 44, &a, 2 * sizeof(double)); L[22] = a[2]; }
  { const v8d a = (0.088484548419542217*g_one) + (-0.0004011109963517577*g5);
    std::memcpy(moment_arm + 46, &a, 2 * sizeof(double)); L[23] = a[2]; }
  { const v8d a = (0.01789255744566345*g0 + -9.2323828529184825e-05*g8) + (0.017491846131347889*g_one);
    std::memcpy(moment_arm + 48, &a, 2 * sizeof(double)); L[24] = a[2]; }
  { const v8d a = (0.013197965256264616*g0) + (0.020978892100383239*g_one);
    std::memcpy(moment_arm + 50, &a, 2 * sizeof(double)); L[25] = a[2]; }
  { const v8d a = (0.024836158501466053*g_one) + (0.01019707058033662*g0);
    std::memcpy(moment_arm + 52, &a, 2 * sizeof(double)); L[26] = a[2]; }
  { const v8d a = (0.026634381389679235*g_one) + (0.0091951219565026363*g0);
    std::memcpy(moment_arm + 54, &a, 2 * sizeof(double)); L[27] = a[2]; }
  { const v8d a = (0.029810017470512391*g_one) + (0.0084851942829559969*g0);
    std::memcpy(moment_arm + 56, &a, 2 * sizeof(double)); L[28] = a[2]; }
  { const v8d a = (0.05219998877607232*g_one) + (-0.0018736609339674755*g2);
    std::memcpy(moment_arm + 58, &a, 2 * sizeof(double)); L[29] = a[2]; }
  { const v8d a = (0.048403047165426483*g_one) + (-0.0023461675721718174*g2);
    std::memcpy(moment_arm + 60, &a, 2 * sizeof(double)); L[30] = a[2]; }
  { const v8d a = (0.050437921269467202*g_one) + (-0.0084292992710578198*g0);
    std::memcpy(moment_arm + 62, &a, 2 * sizeof(double)); L[31] = a[2]; }
  { const v8d a = (0.21575536765481948*g_one) + (0.019051050959109413*g1);
    std::memcpy(moment_arm + 64, &a, 2 * sizeof(double)); L[32] = a[2]; }
  { const v8d a = (0.21823623252684846*g_one) + (0.019047197072656334*g1);
    std::memcpy(moment_arm + 66, &a, 2 * sizeof(double)); L[33] = a[2]; }
  { const v8d a = (0.22228121039050613*g_one) + (0.018490781815815184*g1);
    std::memcpy(moment_arm + 68, &a, 2 * sizeof(double)); L[34] = a[2]; }
  { const v8d a = (0.18493234596763253*g_one) + (0.018452407628263206*g1);
    std::memcpy(moment_arm + 70, &a, 2 * sizeof(double)); L[35] = a[2]; }
  { const v8d a = (0.18110332183018391*g_one) + (0.018332654608435556*g1);
    std::memcpy(moment_arm + 72, &a, 2 * sizeof(double)); L[36] = a[2]; }
  { const v8d a = (0.01890806017308801*g_one + -0.00074217335834553125*g7) + (0.010640416800153787*g1);
    std::memcpy(moment_arm + 74, &a, 2 * sizeof(double)); L[37] = a[2]; }
  { const v8d a = (0.018165371255997188*g_one + -0.0005890501312097794*g7) + (0.010653037188018574*g1);
    std::memcpy(moment_arm + 76, &a, 2 * sizeof(double)); L[38] = a[2]; }
  { const v8d a = (0.020941443241999411*g_one + -0.0036691317712919131*g4) + (0.014024502926364315*g1);
    std::memcpy(moment_arm + 78, &a, 2 * sizeof(double)); L[39] = a[2]; }
  { const v8d a = (0.048264829588007215*g_one) + (0.0045921998027994362*g1);
    std::memcpy(moment_arm + 80, &a, 2 * sizeof(double)); L[40] = a[2]; }
  { const v8d a = (0.033624720221011817*g_one) + (0.005900837864672057*g1);
    std::memcpy(moment_arm + 82, &a, 2 * sizeof(double)); L[41] = a[2]; }
}

void gh_directions(const double* q, double* d) {
  (void)q;
  {
    const double x = -0.57396365917253478;
    const double y = -0.51966034605835165;
    const double z = -0.30229789420071657;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[0] = x*s; d[1] = y*s; d[2] = z*s;
  }
  {
    const double x = -0.34224702721856137;
    const double y = 0.92231716639197281;
    const double z = 0.13808962160250379;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[3] = x*s; d[4] = y*s; d[5] = z*s;
  }
  {
    const double x = -0.34224702721856137;
    const double y = 0.92231716639197281;
    const double z = 0.13808962160250379;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[6] = x*s; d[7] = y*s; d[8] = z*s;
  }
  {
    const double x = -0.28422550305151778;
    const double y = 0.940042793594561;
    const double z = 0.1494606077685372;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[9] = x*s; d[10] = y*s; d[11] = z*s;
  }
  {
    const double x = -0.28751395029967308;
    const double y = 0.93666000134722283;
    const double z = 0.15174591875711696;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[12] = x*s; d[13] = y*s; d[14] = z*s;
  }
  {
    const double x = -0.28297907074343831;
    const double y = 0.93970303633463714;
    const double z = 0.14990002400316696;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[15] = x*s; d[16] = y*s; d[17] = z*s;
  }
  {
    const double x = -0.29392760492651177;
    const double y = 0.93488988209403134;
    const double z = 0.1517018244281646;
    const double n = std::sqrt(x*x + y*y + z*z);
    const double s = n > 0.0 ? 1.0/n : 0.0;
    d[18] = x*s; d[19] = y*s; d[20] = z*s;
  }
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
  d[108] = 0.0; d[109] = 0.0; d[110] = 0.0;
  d[111] = 0.0; d[112] = 0.0; d[113] = 0.0;
  d[114] = 0.0; d[115] = 0.0; d[116] = 0.0;
  d[117] = 0.0; d[118] = 0.0; d[119] = 0.0;
  d[120] = 0.0; d[121] = 0.0; d[122] = 0.0;
  d[123] = 0.0; d[124] = 0.0; d[125] = 0.0;
}

}  // namespace armrt::generated::participant_A_FES
