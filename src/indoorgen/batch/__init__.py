"""Batch dataset generation: many seeds into one directory on a local process pool or a Dask
cluster, resumable and crash-safe (`dataset.make_dataset`), and the dataset's statistics
(`stats`)."""
