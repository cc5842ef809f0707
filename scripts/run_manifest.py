"""The run folder's manifest, .ssc_manifest: ssc lists there every file it
writes into a run folder, before writing it, and the next run into that
folder removes exactly the files listed (docs/architecture.md, interface
contract). A script that draws into a run folder lists its pictures the
same way, so that a rerun does not leave stale pictures beside new results
and never removes a file it did not write.

    fig.savefig(run_manifest.record(run, "force_depth.png"))
"""
import os

MANIFEST = ".ssc_manifest"


def record(folder, name):
    """Lists NAME in FOLDER's manifest (once) and returns its path."""
    manifest = os.path.join(folder, MANIFEST)
    listed = set()
    if os.path.exists(manifest):
        with open(manifest) as f:
            listed = set(f.read().splitlines())
    if name not in listed:
        with open(manifest, "a") as f:
            f.write(name + "\n")
    return os.path.join(folder, name)
