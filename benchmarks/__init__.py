"""Benchmarks of `cagd_ref` against the libraries geometric modellers already use.

`python benchmarks/run.py` measures everything in one run and writes
`benchmarks/results/benchmarks.md` and `benchmarks.png`; `--quick` is a smoke
run on small sizes. `grading.py` is a separate benchmark of `cagd grade`.
"""
