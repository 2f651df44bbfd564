#!/usr/bin/python3
"""bench/cold-start-phases.py -- a cold `bin/ames run` phase by phase, in CPU seconds.

Each command runs as a whole process under a child subreaper, so that the CPU of every
process it starts is counted, Maxima's too (the bridge's Maxima leaves on end of input
after bin/ames exits and is not its reaped child: timing bin/ames alone misses it).
Prints, for RUNS runs each (the median, and the least), the CPU and wall seconds of:
  a bare Maxima start           maxima --very-quiet --batch-string 'quit();'
  Maxima with the bridge's      maxima --very-quiet -p build/gcl/maxima-server.o (the
    compiled request server       server loaded, leaving at once on end of input)
  the command line's start      bin/ames help (the script's check and the image's start)
  the whole cold run            bin/ames run SCENARIO (SBCL, Maxima and the work)
and the whole run as a multiple of the bare start. CPU is what the load changes least
on a shared machine; wall seconds are printed for reference. Asserts nothing.
Run from a checkout, after bin/ames has built its image:
  /usr/bin/python3 bench/cold-start-phases.py [SCENARIO] [RUNS]
"""
import ctypes, os, resource, statistics, sys, time

PR_SET_CHILD_SUBREAPER = 36


def run_once(argv):
    """CPU seconds (user + system) of ARGV and every process it started, and wall seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    pid = os.fork()
    if pid == 0:
        devnull = os.open(os.devnull, os.O_RDWR)
        for fd in (0, 1, 2):
            os.dup2(devnull, fd)
        os.execvp(argv[0], argv)
    while True:                 # the command, then whatever it left behind (Maxima)
        try:
            os.wait()
        except ChildProcessError:
            break
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def main():
    scenario = sys.argv[1] if len(sys.argv) > 1 else "scenarios/particle-on-wedge.lisp"
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    ctypes.CDLL(None).prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
    server = "build/gcl/maxima-server.o"
    if not os.path.exists(server):
        server = "src/maxima-bridge/maxima-server.lisp"
    phases = [("a bare Maxima start", ["maxima", "--very-quiet", "--batch-string", "quit();"]),
              ("Maxima with the request server", ["maxima", "--very-quiet",
                                                  "--init=ames-bridge-no-init", "-p", server]),
              ("bin/ames help (script, image)", ["bin/ames", "help"]),
              ("bin/ames run, whole", ["bin/ames", "run", scenario])]
    figures = {label: [] for label, _ in phases}
    for label, argv in phases:
        run_once(argv)          # a warm-up run: the file cache, an image built
    for _ in range(runs):       # interleaved, so that a change of load touches all alike
        for label, argv in phases:
            figures[label].append(run_once(argv))
    print(f"{scenario}, {runs} runs each (median, least), load average "
          f"{os.getloadavg()[0]:.1f}:")
    for label, _ in phases:
        cpus = [c for c, _ in figures[label]]
        walls = [w for _, w in figures[label]]
        print(f"  {label:32} CPU {statistics.median(cpus):6.3f} s ({min(cpus):6.3f})"
              f"   wall {statistics.median(walls):6.3f} s ({min(walls):6.3f})")
    bare = [c for c, _ in figures["a bare Maxima start"]]
    whole = [c for c, _ in figures["bin/ames run, whole"]]
    ratios = [w / b for w, b in zip(whole, bare)]
    print(f"  the whole run / a bare start, CPU, pair by pair: median "
          f"{statistics.median(ratios):.1f} x (least {min(ratios):.1f} x)")


if __name__ == "__main__":
    main()
