"""Where model files are: the ones loaded in this process (the registry armrt.Model.load fills) and
the shipped models/<name>.json. Below model.py and geometry.py, which both need it."""
from __future__ import annotations

import os
from pathlib import Path

# Model files loaded in this process: name -> (model file, library). Model.load fills it.
LOADED: dict[str, tuple[Path, Path]] = {}


def find_model_file(model: str) -> Path | None:
    """The model file models/<model>.json: the file a model was loaded from (armrt.Model.load), in
    $ARMRT_MODEL_DIR, installed beside the package (armrt/models/), or in the source checkout
    (python/armrt/../../models); None if absent."""
    # A model name is a plain identifier: never a path (a result file's `model` field reaches here).
    if not isinstance(model, str) or not model.replace("_", "").isalnum() or not model.isascii():
        raise ValueError(f"model name must be letters, digits and '_', got {str(model)[:80]!r}")
    if model in LOADED:  # loaded from a file in this process (armrt.Model.load)
        return LOADED[model][0]
    here = Path(__file__).resolve().parent
    dirs = [Path(os.environ["ARMRT_MODEL_DIR"])] if os.environ.get("ARMRT_MODEL_DIR") else []
    dirs += [here / "models", here.parents[1] / "models"]
    for d in dirs:
        if (d / f"{model}.json").exists():
            return d / f"{model}.json"
    return None
