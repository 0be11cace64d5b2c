"""The figures of `zcube reproduce` and `zcube sweep`, drawn by scripts/plot_results.py: a module
per paper, mirroring src/repro/reproduce_<paper>.cpp (kurc, charles, blazek, compositing, fidelity;
calibration, and sweep), each with a draw(opt, ...) that takes the request's Options (common.py)."""
