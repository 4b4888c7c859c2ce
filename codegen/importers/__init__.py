"""DAS-format sources (model_struct*.mat, equilibrium.mat, das3.osim) -> armrt model files: the importers
and the muscle-path fitters. They may use the generator (codegen.polynomial, codegen.eom_chain, ...);
the generator imports nothing from here (tests/test_import_graph.py)."""
