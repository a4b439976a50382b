"""The recipe of docs/book/src/python.md, "A sweep on a Dask cluster": a sweep's shards run on
a local Dask cluster's worker processes and merge to exactly the unsharded summary, and to what
`dvf sweep` prints."""

from __future__ import annotations

import pytest

import dvf
from conftest import bits, cli_json

distributed = pytest.importorskip("distributed")


def test_shards_on_a_local_cluster_merge_to_the_unsharded_summary(dvf_bin):
    from dask.distributed import Client, LocalCluster

    # The book's recipe, with a smaller sweep.
    options = dict(count=12, seed=7, family="random", robots=(2, 6))
    shards = 4
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            futures = [client.submit(dvf.sweep, **options, shard=(k, shards)) for k in range(1, shards + 1)]
            outcomes = [row for rows in client.gather(futures) for row in rows]
            workers = {w for w in client.who_has(futures).values() for w in w}
    summary = dvf.merge(outcomes)

    assert len(outcomes) == 12
    assert workers, "the shards ran on the cluster's workers"
    assert bits(summary) == bits(dvf.sweep(**options))
    printed = cli_json(dvf_bin, "sweep", "--count", "12", "--seed", "7", "--family", "random", "--robots", "2..=6")
    assert bits(summary) == bits(printed)
