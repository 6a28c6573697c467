"""Running the diskimpact of build/ from a bench script."""
import os
import subprocess
import time

BINARY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                      "build", "diskimpact")


def run_diskimpact(prm, ranks):
    """Run build/diskimpact on @p prm on @p ranks MPI ranks (its output
    discarded, an error raised if it fails); return the wall time [s]."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    subprocess.run(["mpirun", "-np", str(ranks), BINARY, prm],
                   check=True, stdout=subprocess.DEVNULL, env=env)
    return time.time() - start
