"""bench/profile_step.py reads callgrind_annotate's call tree as it prints it (a sample of its output, so the
parser is checked without valgrind): costs per function and per callee edge, call counts, short names."""
from bench.profile_step import call_tree

SAMPLE = """\
--------------------------------------------------------------------------------
49,339,645 (100.0%)  PROGRAM TOTALS
49,339,645 (100.0%)  *  ???:armrt::step_ros2(armrt::Model const&, armrt::Data&, armrt::Ros2Workspace&, double, bool) [/x/libarmrt.so]
48,946,845 (99.20%)  >   ???:armrt::(anonymous namespace)::ros2_stages(armrt::Model const&, armrt::Data&) (800x) [/x/libarmrt.so]

48,946,845 (99.20%)  *  ???:armrt::(anonymous namespace)::ros2_stages(armrt::Model const&, armrt::Data&) [/x/libarmrt.so]
17,562,886 (35.60%)  >   ???:armrt::forward_from_paths(armrt::Model const&, double const*) (1,330x) [/x/libarmrt.so]
 3,690,400 ( 7.48%)  >   ???:armrt::jacobian_factor(armrt::Model const&, armrt::StepJacobian&, double) (800x) [/x/libarmrt.so]

 7,230,271 (14.65%)  *  ???:armrt::forward(armrt::Model const&, armrt::Data&) [/x/libarmrt.so]
 1,840,903 ( 3.73%)  >   ???:armrt::generated::das2::muscle_paths(double const*, double*, double*) (6,660x) [/x/libarmrt.so]
 6,824,000 (13.83%)  *  ???:void armrt::(anonymous namespace)::jacobian_solve_n<5>(armrt::Model const&) [/x/libarmrt.so]
"""


def test_call_tree_reads_costs_callees_and_counts():
    tree = call_tree(SAMPLE)
    assert tree["step_ros2"]["cost"] == 49_339_645
    stages = tree["ros2_stages"]
    assert stages["cost"] == 48_946_845
    assert stages["callees"]["forward_from_paths"] == (17_562_886, 1330)
    assert stages["callees"]["jacobian_factor"] == (3_690_400, 800)
    assert tree["forward"]["callees"]["generated muscle_paths"] == (1_840_903, 6660)
    assert tree["jacobian_solve_n<5>"]["cost"] == 6_824_000
    assert "PROGRAM TOTALS" not in tree
