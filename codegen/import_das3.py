"""`python -m codegen.import_das3 ...` -> codegen/importers/import_das3.py's main: the importer command
every model file records as its `source.importer` (models/*.json), kept runnable at that name.

Not part of the generator (tests/test_import_graph.py lets this one module of codegen/ import the
importers); code imports codegen.importers.import_das3 itself.
"""
import sys

from .importers.import_das3 import main

if __name__ == "__main__":
    sys.exit(main())
