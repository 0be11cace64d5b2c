"""Drawing figures side by side: each in a process forked from this one, the plotting modules
loaded once before."""
import gc, os, sys

from plot_figure import subplots


class Pool:
    """Draws each figure (a callable) in a process of its own, forked from this one once the
    plotting modules are loaded, up to `jobs` at once: the figures of `zcube reproduce` then use
    both cores while its last simulations and its calibration end. With jobs = 1 (or --describe,
    whose list of figures lives in this process) they are drawn here, one after the other. A figure
    draws the same bytes in either (Agg's drawing depends on nothing a process learns)."""

    def __init__(self, jobs):
        self.jobs, self.running, self.failed = jobs, set(), 0

    def draw(self, part, *args):
        if self.jobs <= 1:
            part(*args)
            return
        while len(self.running) >= self.jobs:
            self.reap()
        sys.stdout.flush()
        sys.stderr.flush()
        # A collection reads and writes the header of every object it tracks, so in a forked
        # process it copies the inherited pages (copy-on-write): the objects so far are left out
        # of later collections (gc.freeze), and a figure's short-lived process collects nothing.
        gc.freeze()
        pid = os.fork()
        if pid == 0:
            gc.disable()
            status = 1
            try:
                part(*args)
                status = 0
            except BaseException:
                import traceback
                traceback.print_exc()
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(status)
        self.running.add(pid)

    def reap(self):
        pid, status = os.wait()
        self.running.discard(pid)
        self.failed += status != 0

    def wait(self):
        while self.running:
            self.reap()
        if self.failed:
            sys.exit(f"plot_results.py: {self.failed} figure(s) failed")


def warm_up():
    """Loads the fonts and the Agg renderer once, before the figures are forked (each would load
    its own): a small figure with text, drawn to memory."""
    import io
    fig, ax = subplots(figsize=(2, 2))
    ax.set_title("warm-up")
    ax.plot([1, 2], [1, 2], marker="o", label="x")
    ax.legend()
    fig.savefig(io.BytesIO(), dpi=110, format="png")
