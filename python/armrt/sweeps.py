"""`armrt.sweep`: run a function over many items (whole simulations), in-process or as Ray tasks.

    from armrt import sweep
    results = sweep(run_one, grid, backend="ray")        # a local Ray on this machine (ray.init() implicit)
    results = sweep(run_one, grid, backend="ray", address="ray://head:10001")  # an existing cluster
    results = sweep(run_one, grid)                       # backend="local": the same, in this process

Ray (PyPI `ray`) does the farming out, scheduling, retries and cluster management; this module only
submits one task per item, shows a progress bar (tqdm) and gathers results in item order.
"""
from __future__ import annotations

import sys
from typing import Any, Callable, Iterable, Sequence

import numpy as np

from .progress import bar

BACKENDS = ("local", "ray")


def _progress(total: int, desc: str | None, enabled: bool | None):
    """The bar every armrt loop shows (progress.bar: None = only when stderr is a terminal)."""
    return bar(total, desc or "sweep", unit="item", enabled=enabled, delay=0.0 if enabled else 1.0)


def gather(results: Sequence[Any]):
    """Results as arrays where they fit: numbers or equal-shape arrays -> one stacked ndarray (items
    first); dicts with the same keys -> a dict of such arrays (each key gathered alike); otherwise
    the list unchanged."""
    if not results:
        return list(results)
    first = results[0]
    if isinstance(first, dict):
        keys = list(first)
        if all(isinstance(r, dict) and list(r) == keys for r in results):
            return {k: gather([r[k] for r in results]) for k in keys}
        return list(results)
    try:
        arrays = [np.asarray(r) for r in results]
    except Exception:  # ragged or exotic objects
        return list(results)
    if all(a.dtype != object and a.shape == arrays[0].shape for a in arrays):
        return np.stack(arrays)
    return list(results)


def sweep(fn: Callable[[Any], Any], items: Iterable[Any], backend: str = "local", *, address: str | None = None,
          num_cpus_per_task: float = 1.0, progress: bool | None = None, desc: str | None = None, stack: bool = True,
          ray_init: dict | None = None):
    """Returns fn(item) for each item, in the order of `items`.

    backend="local" calls fn in this process, one item after another. backend="ray" submits each call
    as a Ray task (`num_cpus_per_task` CPUs each; Ray runs as many at once as the cluster has CPUs)
    and waits for them all. With no Ray running, ray.init() is called for you: a local Ray on this
    machine, or the cluster at `address` ("auto", "ray://host:10001", ...); `ray_init` passes further
    keyword arguments to ray.init (e.g. num_cpus). An existing ray.init() of yours is used as is.
    fn and the items must pickle (cloudpickle: lambdas and closures are fine; a function from a
    module that is not an installed package is shipped by value), and on a cluster every node needs
    armrt installed.

    With `stack` (default) results are gathered as arrays (see gather()); otherwise a list.
    A progress bar (tqdm) on stderr counts finished items: progress None (default) shows it only on a
    terminal, and only once the sweep has run for a second; True always; False never.
    Raises ValueError for an unknown backend, ImportError if Ray is needed and missing, and
    re-raises the first exception raised by fn (Ray wraps it in a RayTaskError that names the item's
    task and carries the original traceback).
    """
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; expected one of {BACKENDS}")
    items = list(items)
    if backend == "local":
        out = []
        with _progress(len(items), desc, progress) as bar:
            for item in items:
                out.append(fn(item))
                bar.update(1)
    else:
        out = _sweep_ray(fn, items, address, num_cpus_per_task, progress, desc, ray_init or {})
    return gather(out) if stack else out


def _sweep_ray(fn, items, address, num_cpus_per_task, progress, desc, ray_init):
    try:
        import ray
    except ImportError:
        raise ImportError("backend='ray' needs Ray: pip install 'ray>=2.9' (or use backend='local')") from None
    if not ray.is_initialized():
        kwargs = {"include_dashboard": False, "ignore_reinit_error": True, "log_to_driver": False, **ray_init}
        ray.init(address=address, **kwargs)
    _ship_local_module(fn)
    remote = ray.remote(num_cpus=num_cpus_per_task)(fn)
    refs = [remote.remote(item) for item in items]
    index = {ref: k for k, ref in enumerate(refs)}
    out: list = [None] * len(refs)
    pending = list(refs)
    with _progress(len(refs), desc, progress) as bar:
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            for ref in done:
                out[index[ref]] = ray.get(ref)  # raises the task's exception, if any
                bar.update(1)
    return out


def _ship_local_module(fn) -> None:
    """Ray pickles a function by reference to its module, which workers must import. A function from
    a module that is not an installed package (a script's neighbour, a test file) is shipped by
    value instead, as functions of a script's __main__ already are."""
    name = getattr(fn, "__module__", None)
    if not name or name == "__main__" or name not in sys.modules:
        return
    import importlib.metadata  # here, not at import: it costs `import armrt` about 50 ms (bench.first_step)
    top = name.split(".")[0]
    if top in sys.stdlib_module_names or top in importlib.metadata.packages_distributions():
        return
    from ray import cloudpickle
    cloudpickle.register_pickle_by_value(sys.modules[name])
