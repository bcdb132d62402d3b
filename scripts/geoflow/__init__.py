"""geoflow's Python pieces shared by the drivers (scripts/hybrid_run.py, scripts/column_collapse/study.py):

    pipeline  running fem_tcl, fem2mpm and mpm (the FEM output contract, errors, wall times)
    metrics   reading recorder files, model.json, series.csv and particle files; the metrics of DESIGN.md
    plots     matplotlib figures (Agg backend, PNG)

Only /usr/bin/python3 with Debian's numpy, matplotlib and h5py.
"""
