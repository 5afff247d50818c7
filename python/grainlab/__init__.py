"""grainlab from Python: parameter sweeps of `grainlab run` on Dask (grainlab.sweep)."""
