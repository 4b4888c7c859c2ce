"""Range of motion of the fixed-scapula arm, used for fitting the path polynomials and as the
limits of the passive joint moments (the engine applies stiff passive moments outside it, so the
arm stays inside the box the polynomials were fitted over).

The paper restricted Gunal et al.'s ranges "where necessary in order to ensure correct wrapping";
its Table I did not survive, so the limits are chosen here, all inside the DAS3 ranges
(model_struct ``dofs[i].range``), around the DAS3 resting posture (equilibrium.mat x[6:11] =
GHy 0.434, GHz 0.498, GHyy 0.273, ELx 0.657, PSy 1.421 rad) and covering the paper's experiments
(arm hanging with small axial-rotation changes; humeral elevation by the deltoid roughly in the
scapular plane up to the GHz limit; elbow flexion 5-140 deg; pronation 5-160 deg). The reasons
come from OpenSim sweeps of every GH-crossing element through the resting posture at GHz = 0.3,
0.5, 1.0 and 1.4 (second differences of ``computeMomentArm`` for kinks, and the wrap-jump test of
``codegen.importers.opensim_geometry`` for poses where it disagrees with the length derivative):

* ``GHz`` (humeral elevation in the plane set by ``GHy``) 0.25 .. 1.466 rad. The upper limit is the
  DAS3 limit: with the scapula fixed this is a thoracohumeral elevation of about 70 deg, the most
  the gleno-humeral joint alone allows, and what deltoid stimulation reaches in the paper. Below
  0 the y-z-y gimbal re-describes the same arm directions with ``GHy`` turned by 180 deg, and the
  subscapularis and clavicular deltoid fits were worst in the lowest band (0.25-0.35: 4.7% of
  element-poses over the criterion against ~3% elsewhere), so the range stops at 0.25 (arm
  against the trunk, humerus about 15 deg from the vertical).
* ``GHy`` (plane of elevation) -0.10 .. 1.00 rad, -31/+33 deg around the resting plane 0.434
  (about the scapular plane). Outside it the deltoid wraps engage and release over the humeral
  head: the clavicular deltoid kinks at GHy -0.3 (GHz 0.5), the pectoralis major clavicular part
  at -0.8..-1.0, the scapular deltoid (deltscap4) at 1.5 and deltscap7 at 1.8 (GHz 1.0), and
  infraspinatus 4-6 have wrap-jump poses from GHy 0.7-1.2 upward at GHz 1.4. The earlier range
  (-0.9 .. 1.5) gave the most criterion failures at both ends (6.0% and 4.5% of element-poses).
  What the box cannot avoid: inside it, the most anterior scapular deltoid fibres flip over the
  humeral head during elevation (deltscap1 at GHy 0.55: GHz moment arm -25 -> +23 mm between GHz
  1.18 and 1.25; deltscap2 the same at GHy 0.8, GHz 1.05), and infraspinatus 6 steps by 20 mm near
  GHz 1.15. These ridges cross the scapular-plane elevation of the paper's deltoid experiment, so
  they are left in the range; the polynomials smooth them and those elements miss the criterion
  near the ridge (docs/path_accuracy.md).
* ``GHyy`` (axial rotation) -0.25 .. 0.80 rad, -30/+30 deg around the resting 0.273. At high
  elevation (GHz 1.4) the infraspinatus cylinder wrap gives moment arms that disagree with the
  length derivative from GHyy 0.2-0.4 upward (infra2-5) and teres minor from 1.5; at GHz 1.0
  infra4 from 1.0 and infra5/6 from 1.56; the earlier range (-1.0 .. 1.2) had 6.1% and 5.2% of
  element-poses over the criterion in its end bands.
* ``ELx`` (elbow flexion) 0.0873 .. 2.443 rad and ``PSy`` (pronation) 0.0873 .. 2.793 rad: the DAS3
  ranges unchanged (5-140 deg and 5-160 deg), which are exactly the motions of the paper's
  experiments. The few wrap jumps inside them (pronator quadratus at full supination, pronator
  teres near 55 deg pronation) are single poses that the fit excludes and reports.
"""

ROM: dict[str, tuple[float, float]] = {
    "GHy": (-0.10, 1.00),
    "GHz": (0.25, 1.4661),
    "GHyy": (-0.25, 0.80),
    "ELx": (0.08726646, 2.44346095),
    "PSy": (0.08726646, 2.7925268),
}
