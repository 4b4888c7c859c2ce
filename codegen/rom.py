"""Range of motion of the fixed-scapula arm, used for fitting the path polynomials and as the
limits of the passive joint moments.

The paper's Table I (Gunal et al. ranges, narrowed where SIMM wrapping misbehaved) did not survive,
so the limits are chosen here, all inside the DAS3 ranges (model_struct ``dofs[i].range``):

* ``GHz`` (humeral elevation in the plane set by ``GHy``) 0.1 .. 1.466 rad. The upper limit is the
  DAS3 limit: with the scapula fixed at the equilibrium posture this is a thoracohumeral elevation
  of about 70 deg, the most the gleno-humeral joint alone allows, and it is what deltoid stimulation
  can reach. Below 0 the y-z-y gimbal re-describes the same arm directions with ``GHy`` turned by
  180 deg (DAS3 allows -0.52 only for its own girdle motion); the infraspinatus cylinder wrap gives
  OpenSim moment arms that drift away from the length derivative there, and the subscapularis and
  clavicular deltoid fits are worst at low elevation, so the range stops at 0.25 (arm against the
  trunk, humerus about 15 deg from the vertical).
* ``GHy`` (plane of elevation) -0.9 .. 1.5 rad: from the scapular plane through the sagittal plane
  to adduction across the chest, about -75/+60 deg around the resting plane 0.43; the lower limit
  was pulled in from -1.2 because deltoid and subscapularis moment arms kink (sphere-wrap
  engagement) there. Beyond it (DAS3 allows the whole circle) the teres minor and infraspinatus
  wraps jump (moment arms off by 30-50 mm at GHy ~ 2.5) and the arm would pass through the trunk.
* ``GHyy`` (axial rotation) -1.0 .. 1.2 rad: about +-65 deg around the resting 0.27, the arc over
  which the rotator cuff stays on its humeral-head wrap surfaces; teres minor flips side on its
  cylinder near 2 rad.
* ``ELx`` (elbow flexion) 0.0873 .. 2.443 rad and ``PSy`` (pronation) 0.0873 .. 2.793 rad: the DAS3
  ranges unchanged (5-140 deg and 5-160 deg), which are exactly the motions of the paper's
  experiments. The few wrap jumps inside them (pronator quadratus at full supination, pronator
  teres near 55 deg pronation) are single poses that the fit excludes and reports.

The DAS3 resting posture (equilibrium.mat x[6:11] = 0.434, 0.498, 0.273, 0.657, 1.421) lies inside.
"""

ROM: dict[str, tuple[float, float]] = {
    "GHy": (-0.9, 1.5),
    "GHz": (0.25, 1.4661),
    "GHyy": (-1.0, 1.2),
    "ELx": (0.08726646, 2.44346095),
    "PSy": (0.08726646, 2.7925268),
}
