// GENERATED FILE - DO NOT EDIT BY HAND.
// Written by `python -m codegen.generate --model models/participant_A.json --out cpp/generated`
// from the model file participant_A.json (sha256 903af86a45ee66c979ac5c63507d6bdfa5c9f74282ceae7acb5ee37214a160bd).
// Change the model file or the generator and regenerate instead.

#include <cmath>
#include <cstring>

#include "participant_A.h"

namespace armrt::generated::participant_A {

// muscle_paths writes its moment arms in rows of 160 (model_def.h): the engine must agree.
static_assert(kMaxElements == 160, "rebuild this model: the engine's kMaxElements changed");

// Eight doubles, one SIMD register with AVX-512 (two with AVX2): a length and its moment arms.
using v8d = double __attribute__((vector_size(64)));

void muscle_lengths(const double* q, double* L) {
  double moment_arm[2 * kMaxElements];
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
    moment_arm[0 * kMaxElements + 0] = a[0]; moment_arm[1 * kMaxElements + 0] = a[1]; L[0] = a[2]; }
  { const v8d a = (0.33473066287360076*g_one + 0.0015576962817986635*g11) + (-0.021160884811199852*g1 + -0.01710614612749067*g4);
    moment_arm[0 * kMaxElements + 1] = a[0]; moment_arm[1 * kMaxElements + 1] = a[1]; L[1] = a[2]; }
  { const v8d a = (0.33473066287360076*g_one + 0.0015576962817986635*g11) + (-0.021160884811199852*g1 + -0.01710614612749067*g4);
    moment_arm[0 * kMaxElements + 2] = a[0]; moment_arm[1 * kMaxElements + 2] = a[1]; L[2] = a[2]; }
  { const v8d a = (0.28338136608271164*g_one) + (0.018303606851437355*g1);
    moment_arm[0 * kMaxElements + 3] = a[0]; moment_arm[1 * kMaxElements + 3] = a[1]; L[3] = a[2]; }
  { const v8d a = (0.28719747442926685*g_one) + (0.018333913075011372*g1);
    moment_arm[0 * kMaxElements + 4] = a[0]; moment_arm[1 * kMaxElements + 4] = a[1]; L[4] = a[2]; }
  { const v8d a = (0.31510939348476741*g_one) + (0.018347585403952173*g1);
    moment_arm[0 * kMaxElements + 5] = a[0]; moment_arm[1 * kMaxElements + 5] = a[1]; L[5] = a[2]; }
  { const v8d a = (0.31090321429854784*g_one) + (0.018333298313063819*g1);
    moment_arm[0 * kMaxElements + 6] = a[0]; moment_arm[1 * kMaxElements + 6] = a[1]; L[6] = a[2]; }
  { const v8d a = (0.14439930529052919*g_one) + (0.018495944824771921*g1);
    moment_arm[0 * kMaxElements + 7] = a[0]; moment_arm[1 * kMaxElements + 7] = a[1]; L[7] = a[2]; }
  { const v8d a = (0.16636600881321539*g_one) + (0.018586457750819772*g1);
    moment_arm[0 * kMaxElements + 8] = a[0]; moment_arm[1 * kMaxElements + 8] = a[1]; L[8] = a[2]; }
  { const v8d a = (0.05784840143603056*g_one) + (0.01791288105182116*g1);
    moment_arm[0 * kMaxElements + 9] = a[0]; moment_arm[1 * kMaxElements + 9] = a[1]; L[9] = a[2]; }
  { const v8d a = (0.09401411952021374*g_one) + (0.018633170621684413*g1);
    moment_arm[0 * kMaxElements + 10] = a[0]; moment_arm[1 * kMaxElements + 10] = a[1]; L[10] = a[2]; }
  { const v8d a = (0.13495576823678765*g_one) + (0.018639947486272394*g1);
    moment_arm[0 * kMaxElements + 11] = a[0]; moment_arm[1 * kMaxElements + 11] = a[1]; L[11] = a[2]; }
  { const v8d a = (0.18054915365586605*g_one + -0.013490244982363779*g4) + (-0.010064018125658672*g1 + 0.00076035805702999904*g11);
    moment_arm[0 * kMaxElements + 12] = a[0]; moment_arm[1 * kMaxElements + 12] = a[1]; L[12] = a[2]; }
  { const v8d a = (0.17185614884687686*g_one + -0.013129924628792021*g4) + (-0.010607947535131135*g1 + 0.00081655498087052872*g11);
    moment_arm[0 * kMaxElements + 13] = a[0]; moment_arm[1 * kMaxElements + 13] = a[1]; L[13] = a[2]; }
  { const v8d a = (0.13788023815200173*g_one + -0.0072621398786317766*g4) + (-0.011003570164694533*g1 + 0.00041496150926974642*g11);
    moment_arm[0 * kMaxElements + 14] = a[0]; moment_arm[1 * kMaxElements + 14] = a[1]; L[14] = a[2]; }
  { const v8d a = (0.13682594851170329*g_one + -0.012179475703005739*g4) + (-0.010436576094386672*g1 + 0.00068531720259456413*g11);
    moment_arm[0 * kMaxElements + 15] = a[0]; moment_arm[1 * kMaxElements + 15] = a[1]; L[15] = a[2]; }
  { const v8d a = (0.10582993268499524*g_one + -0.013492577373902323*g1) + (-0.0049417943619925603*g4);
    moment_arm[0 * kMaxElements + 16] = a[0]; moment_arm[1 * kMaxElements + 16] = a[1]; L[16] = a[2]; }
  { const v8d a = (0.093340573418945791*g_one + -0.0027620542580382044*g4) + (-0.015846561972244409*g1);
    moment_arm[0 * kMaxElements + 17] = a[0]; moment_arm[1 * kMaxElements + 17] = a[1]; L[17] = a[2]; }
  { const v8d a = (0.092937201092718247*g_one + -0.01356394993162429*g1) + (-0.0053083636125351823*g4);
    moment_arm[0 * kMaxElements + 18] = a[0]; moment_arm[1 * kMaxElements + 18] = a[1]; L[18] = a[2]; }
  { const v8d a = (0.32798783792991626*g_one + 0.0036820443339514908*g3 + 0.0019519514988018006*g11 + -0.00012142088771236638*g8) + (-0.014081506550507257*g1 + -0.0319387052103242*g4 + -0.00038655735326601442*g10 + 0.0014608349688563225*g2);
    moment_arm[0 * kMaxElements + 19] = a[0]; moment_arm[1 * kMaxElements + 19] = a[1]; L[19] = a[2]; }
  { const v8d a = (0.31383274558971735*g_one + 0.0037104254165799123*g3 + -0.00034214544627906332*g10 + 0.0014702905374723914*g2) + (-0.030540391344434877*g4 + 0.0016782957038975472*g11 + -0.00010386587008950145*g8 + -0.0018017545046243092*g0);
    moment_arm[0 * kMaxElements + 20] = a[0]; moment_arm[1 * kMaxElements + 20] = a[1]; L[20] = a[2]; }
  { const v8d a = (0.30135801351578945*g_one + 0.0036676425316075445*g3 + -0.00028227899507158634*g10 + 0.0006949498177318223*g5 + -5.9126560657371762e-05*g9) + (-0.023399302047159339*g4 + 0.0012285860000156692*g11 + -0.00017256119665149788*g8 + -0.0022029168221863768*g0);
    moment_arm[0 * kMaxElements + 21] = a[0]; moment_arm[1 * kMaxElements + 21] = a[1]; L[21] = a[2]; }
  { const v8d a = (0.16748698437964138*g_one + -0.0002289055349319931*g5) + (-0.0073588586514760912*g1);
    moment_arm[0 * kMaxElements + 22] = a[0]; moment_arm[1 * kMaxElements + 22] = a[1]; L[22] = a[2]; }
  { const v8d a = (0.088484548419542217*g_one) + (-0.0004011109963517577*g5);
    moment_arm[0 * kMaxElements + 23] = a[0]; moment_arm[1 * kMaxElements + 23] = a[1]; L[23] = a[2]; }
  { const v8d a = (0.01789255744566345*g0 + -9.2323828529184825e-05*g8) + (0.017491846131347889*g_one);
    moment_arm[0 * kMaxElements + 24] = a[0]; moment_arm[1 * kMaxElements + 24] = a[1]; L[24] = a[2]; }
  { const v8d a = (0.013197965256264616*g0) + (0.020978892100383239*g_one);
    moment_arm[0 * kMaxElements + 25] = a[0]; moment_arm[1 * kMaxElements + 25] = a[1]; L[25] = a[2]; }
  { const v8d a = (0.024836158501466053*g_one) + (0.01019707058033662*g0);
    moment_arm[0 * kMaxElements + 26] = a[0]; moment_arm[1 * kMaxElements + 26] = a[1]; L[26] = a[2]; }
  { const v8d a = (0.026634381389679235*g_one) + (0.0091951219565026363*g0);
    moment_arm[0 * kMaxElements + 27] = a[0]; moment_arm[1 * kMaxElements + 27] = a[1]; L[27] = a[2]; }
  { const v8d a = (0.029810017470512391*g_one) + (0.0084851942829559969*g0);
    moment_arm[0 * kMaxElements + 28] = a[0]; moment_arm[1 * kMaxElements + 28] = a[1]; L[28] = a[2]; }
  { const v8d a = (0.05219998877607232*g_one) + (-0.0018736609339674755*g2);
    moment_arm[0 * kMaxElements + 29] = a[0]; moment_arm[1 * kMaxElements + 29] = a[1]; L[29] = a[2]; }
  { const v8d a = (0.048403047165426483*g_one) + (-0.0023461675721718174*g2);
    moment_arm[0 * kMaxElements + 30] = a[0]; moment_arm[1 * kMaxElements + 30] = a[1]; L[30] = a[2]; }
  { const v8d a = (0.050437921269467202*g_one) + (-0.0084292992710578198*g0);
    moment_arm[0 * kMaxElements + 31] = a[0]; moment_arm[1 * kMaxElements + 31] = a[1]; L[31] = a[2]; }
  { const v8d a = (0.21575536765481948*g_one) + (0.019051050959109413*g1);
    moment_arm[0 * kMaxElements + 32] = a[0]; moment_arm[1 * kMaxElements + 32] = a[1]; L[32] = a[2]; }
  { const v8d a = (0.21823623252684846*g_one) + (0.019047197072656334*g1);
    moment_arm[0 * kMaxElements + 33] = a[0]; moment_arm[1 * kMaxElements + 33] = a[1]; L[33] = a[2]; }
  { const v8d a = (0.22228121039050613*g_one) + (0.018490781815815184*g1);
    moment_arm[0 * kMaxElements + 34] = a[0]; moment_arm[1 * kMaxElements + 34] = a[1]; L[34] = a[2]; }
  { const v8d a = (0.18493234596763253*g_one) + (0.018452407628263206*g1);
    moment_arm[0 * kMaxElements + 35] = a[0]; moment_arm[1 * kMaxElements + 35] = a[1]; L[35] = a[2]; }
  { const v8d a = (0.18110332183018391*g_one) + (0.018332654608435556*g1);
    moment_arm[0 * kMaxElements + 36] = a[0]; moment_arm[1 * kMaxElements + 36] = a[1]; L[36] = a[2]; }
  { const v8d a = (0.01890806017308801*g_one + -0.00074217335834553125*g7) + (0.010640416800153787*g1);
    moment_arm[0 * kMaxElements + 37] = a[0]; moment_arm[1 * kMaxElements + 37] = a[1]; L[37] = a[2]; }
  { const v8d a = (0.018165371255997188*g_one + -0.0005890501312097794*g7) + (0.010653037188018574*g1);
    moment_arm[0 * kMaxElements + 38] = a[0]; moment_arm[1 * kMaxElements + 38] = a[1]; L[38] = a[2]; }
  { const v8d a = (0.020941443241999411*g_one + -0.0036691317712919131*g4) + (0.014024502926364315*g1);
    moment_arm[0 * kMaxElements + 39] = a[0]; moment_arm[1 * kMaxElements + 39] = a[1]; L[39] = a[2]; }
  { const v8d a = (0.048264829588007215*g_one) + (0.0045921998027994362*g1);
    moment_arm[0 * kMaxElements + 40] = a[0]; moment_arm[1 * kMaxElements + 40] = a[1]; L[40] = a[2]; }
  { const v8d a = (0.033624720221011817*g_one) + (0.005900837864672057*g1);
    moment_arm[0 * kMaxElements + 41] = a[0]; moment_arm[1 * kMaxElements + 41] = a[1]; L[41] = a[2]; }
}

void gh_directions(const double* q, double* d) {
  (void)q;
  using v3d = double __attribute__((vector_size(32)));  // x, y, z and an unused lane
  double gx[42], gy[42], gz[42];
  { const v3d g = v3d{-0.57396365917253478, -0.51966034605835165, -0.30229789420071657, 0.0}; gx[0] = g[0]; gy[0] = g[1]; gz[0] = g[2]; }
  { const v3d g = v3d{-0.34224702721856137, 0.92231716639197281, 0.13808962160250379, 0.0}; gx[1] = g[0]; gy[1] = g[1]; gz[1] = g[2]; }
  { const v3d g = v3d{-0.34224702721856137, 0.92231716639197281, 0.13808962160250379, 0.0}; gx[2] = g[0]; gy[2] = g[1]; gz[2] = g[2]; }
  { const v3d g = v3d{-0.28422550305151778, 0.940042793594561, 0.1494606077685372, 0.0}; gx[3] = g[0]; gy[3] = g[1]; gz[3] = g[2]; }
  { const v3d g = v3d{-0.28751395029967308, 0.93666000134722283, 0.15174591875711696, 0.0}; gx[4] = g[0]; gy[4] = g[1]; gz[4] = g[2]; }
  { const v3d g = v3d{-0.28297907074343831, 0.93970303633463714, 0.14990002400316696, 0.0}; gx[5] = g[0]; gy[5] = g[1]; gz[5] = g[2]; }
  { const v3d g = v3d{-0.29392760492651177, 0.93488988209403134, 0.1517018244281646, 0.0}; gx[6] = g[0]; gy[6] = g[1]; gz[6] = g[2]; }
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
  gx[36] = 0.0; gy[36] = 0.0; gz[36] = 0.0;
  gx[37] = 0.0; gy[37] = 0.0; gz[37] = 0.0;
  gx[38] = 0.0; gy[38] = 0.0; gz[38] = 0.0;
  gx[39] = 0.0; gy[39] = 0.0; gz[39] = 0.0;
  gx[40] = 0.0; gy[40] = 0.0; gz[40] = 0.0;
  gx[41] = 0.0; gy[41] = 0.0; gz[41] = 0.0;
  for (int i = 0; i < 42; ++i) {
    const double n2 = gx[i]*gx[i] + gy[i]*gy[i] + gz[i]*gz[i];
    const double s = n2 > 0.0 ? 1.0/std::sqrt(n2) : 0.0;
    d[3*i] = gx[i]*s; d[3*i + 1] = gy[i]*s; d[3*i + 2] = gz[i]*s;
  }
}

}  // namespace armrt::generated::participant_A
