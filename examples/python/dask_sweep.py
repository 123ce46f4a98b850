"""A V_stick sweep on a Dask cluster: a LocalCluster by default, or a running one.

    pip install 'stickiness[sweep]'                           # dask.distributed and pandas
    python examples/python/dask_sweep.py                      # a LocalCluster of 2 processes
    python examples/python/dask_sweep.py --scheduler tcp://host:8786
    python examples/python/dask_sweep.py --out sweep.csv

The grid is split into chunks (every T_vis of one material and radius, the searches seeded by
their neighbours) that are mapped over the workers; a lost worker costs a recomputed chunk. The
result equals the in-process `st.sweep(...)` and the CLI's `stickiness sweep`. For a Slurm
cluster, make the client from dask-jobqueue's SLURMCluster instead; nothing else changes.
"""

import argparse

import numpy as np
from distributed import Client, LocalCluster

import stickiness as st


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--scheduler", help="address of a running Dask scheduler")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster workers (default 2)")
    p.add_argument("--out", help="write the DataFrame to this CSV file")
    args = p.parse_args()
    grid = dict(
        material=["co2", "h2o"],
        radius=np.geomspace(1e-6, 1e-4, 9),
        t_vis=np.geomspace(1e-12, 1e-8, 5),
    )
    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=args.workers, processes=True, threads_per_worker=1)
        client = Client(cluster)
    try:
        df = st.sweep(**grid, client=client)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    # SI units; NaN: no bouncing below the search limit (beyond the cliff), see no_bouncing_below
    columns = ["material", "radius", "t_vis", "v_stick", "v_frag", "no_bouncing_below"]
    print(df[columns].to_string(max_rows=12, float_format="{:.4g}".format))
    if args.out:
        df.to_csv(args.out, index=False)
        print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
