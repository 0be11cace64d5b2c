#!/usr/bin/env python3
"""Hostile input by class, each class a batch of generated members (a seeded random choice, so a
failure can be replayed with its seed): platform files edited by hand the ways a what-if user
might, outputs that cannot be written, and platform files written with what-ifs read back.

Every member must end as zcube's contract says: exit 0 with a correct result, 1 for a run that
failed, 2 for bad input found before the simulation; on 1 or 2 exactly one line on stderr, naming
the file; never a signal, a hang, library text (a SimGrid backtrace, "stoi", "json.exception") or
exit 0 where the member is refused.

usage: hostile_classes.py ZCUBE SOURCE_DIR CLASS [--count N] [--seed S]
classes: config structure overflow roundtrip stdout fifo device"""
import argparse, json, os, random, re, signal, stat, subprocess, sys, tempfile

SMALL = ["--size", "16x16"]
LIBRARY_TEXT = re.compile(r"stoi|stol|json\.exception|Backtrace|xbt_|Assertion|terminate called|"
                          r"malloc\(\)|Access violation|core dumped|basic_string")


class Runner:
    def __init__(self, zcube, src, tmp):
        self.zcube, self.src, self.tmp, self.wrong, self.members = zcube, src, tmp, 0, 0

    def base(self, machine, nodes, topology="cube", extra=()):
        path = os.path.join(self.tmp, f"base-{machine}-{topology}-{nodes}.xml")
        if not os.path.exists(path):
            subprocess.run([self.zcube, "platform", "--machine", machine, "--nodes", str(nodes),
                            "--topology", topology, *extra, "-o", path], check=True)
        with open(path) as f:
            return f.read()

    def check(self, name, cmd, want, named=None, timeout=60, stdout=subprocess.DEVNULL):
        """want: a set of accepted exit statuses; named: text the one error line must hold."""
        self.members += 1
        try:
            p = subprocess.run(cmd, stdout=stdout, stderr=subprocess.PIPE, timeout=timeout)
            rc, err = p.returncode, p.stderr.decode(errors="replace")
        except subprocess.TimeoutExpired:
            rc, err = "hang", ""
        lines = err.splitlines()
        why = None
        if rc == "hang":
            why = f"no answer in {timeout} s"
        elif rc < 0:
            why = f"killed by {signal.Signals(-rc).name}"
        elif rc not in want:
            why = f"exit {rc}, want {sorted(want)}"
        elif rc != 0 and len(lines) != 1:
            why = f"{len(lines)} lines on stderr"
        elif LIBRARY_TEXT.search(err):
            why = "library text"
        elif rc != 0 and named and named not in err:
            why = f"the error does not name '{named}'"
        if why:
            self.wrong += 1
            print(f"FAIL {name}: {why}: {err.strip()[:300]!r}")
        else:
            print(f"ok   {name} (exit {rc}): {lines[0][:160] if lines else ''}")
        return rc

    def run_file(self, name, xml, want, extra=(), nodes_flag=True):
        path = os.path.join(self.tmp, name + ".xml")
        with open(path, "w", errors="surrogateescape") as f:
            f.write(xml)
        # Kurc et al.'s pixel merging runs on cubes; Charles et al.'s elastic program on rings too.
        algorithm = "elastic" if 'value="ring"' in xml else "pair-rs"
        cmd = [self.zcube, "run", "--machine", path, "--scene",
               os.path.join(self.src, "scenes/kurc/1pot.json"), *SMALL, "--algorithm", algorithm,
               *extra]
        return self.check(name, cmd, want, named=os.path.basename(path))


def in_config(xml, props):
    for k, v in list(props):  # a key the file sets already: its value replaced
        if f'<prop id="{k}" value="' in xml:
            xml = re.sub(rf'<prop id="{re.escape(k)}" value="[^"]*"', f'<prop id="{k}" value="{v}"', xml)
            props.remove((k, v))
    return xml.replace("  </config>", "".join(
        f'    <prop id="{k}" value="{v}"/>\n' for k, v in props) + "  </config>", 1)


# --- <config> settings: the --cfg allow-list and its ranges hold in a file too.
def gen_config(r, rng, count):
    refused = [
        lambda: ("contexts/stack-size", str(rng.randint(0, 255))),
        lambda: ("contexts/nthreads", str(rng.randint(2, 64))),
        lambda: ("maxmin/precision", rng.choice(["0", "-1", "1e10", "0.5", "nan", "1e-300"])),
        lambda: ("surf/precision", rng.choice(["0", "-1e-9", "1", "inf"])),
        lambda: ("network/bandwidth-factor", rng.choice(["0", "-1", "2", "1e-9"])),
        lambda: ("network/model", rng.choice(["Bogus", "ptask_L07", "IB", "ns-3", "cm02", ""])),
        lambda: ("network/crosstraffic", rng.choice(["maybe", "2", "yess"])),
        lambda: ("contexts/factory", rng.choice(["fibers", "java", "x"])),
        lambda: (rng.choice(["tracing", "tracing/filename", "tracing/platform", "host/model",
                             "cpu/model", "exception/cutpath", "plugin", "debug/breakpoint",
                             "contexts/synchro", "storage/max_file_descriptors",
                             "smpi/simulate-computation", "path", "foo/bar"]),
                 rng.choice(["yes", "1", "x.trace", "energy", "0"])),
        lambda: ("smpi/bw-factor", rng.choice(["0:2", "garbage", "1:1;0:0"])),
    ]
    accepted = [("network/model", "LV08"), ("maxmin/precision", "1e-9"),
                ("contexts/stack-size", "512"), ("network/crosstraffic", "0")]
    for i in range(count):
        machine = rng.choice([("ipsc2", 4, "cube"), ("volvox", 4, "ring"), ("ipsc860", 2, "cube")])
        fidelity = rng.choice(["circuit", "flow", "analytic"])
        xml = r.base(*machine)
        if i % 5 == 4:
            k, v = rng.choice(accepted)
            r.run_file(f"config-{i}-{k.replace('/', '_')}-ok", in_config(xml, [(k, v)]), {0},
                       ["--fidelity", fidelity])
            continue
        k, v = rng.choice(refused)()
        r.run_file(f"config-{i}-{k.replace('/', '_')}", in_config(xml, [(k, v)]), {2},
                   ["--fidelity", fidelity])
        if i == 0:  # a <prop> without its value
            r.run_file("config-no-value", xml.replace('value="CM02"', "", 1), {2})


# --- Structure beyond what zcube models, and text that is not a platform at all.
def nested_zones(xml, depth):
    start = xml.index("  <zone ")
    end = xml.rindex("</platform>")
    opens = "".join(f'<zone id="wrap{d}" routing="Full">' for d in range(depth))
    return xml[:start] + opens + xml[start:end] + "</zone>" * depth + "\n" + xml[end:]


def structure_members(rng, cube, ring):
    route = re.search(r"      <route [^\n]*</route>\n", ring).group(0)
    link = re.search(r'      <link id="ch-[^\n]*/>\n', ring).group(0)
    host = re.search(r"      <host [^\n]*</host>\n", ring).group(0)
    elem = rng.choice(["actor", "trace", "trace_connect", "include", "random", "router",
                       "backbone", "peer", "disk", "storage_type", "mount", "bypassRoute", "AS",
                       "ASroute", "process", "argument", "cabinet", "model_prop"])
    attr = rng.choice(["core", "speed_file", "availability_file", "state_file", "pstate",
                       "coordinates", "bandwidth_file", "latency_file", "loopback_bw", "bb_bw",
                       "limiter_link", "router_id", "foo"])
    value = rng.choice(["0", "-1", "2", "99999999999", "abc", "/etc/hostname", "", "1e3",
                        "/nonexistent"])
    big = rng.choice(["0-99999999999", "0-3,2-3", "3-0", "0-2000", "a-b", "0--1", ","])
    cut = rng.randint(1, len(cube) - 2)
    flips = bytearray(cube.encode())
    for _ in range(rng.randint(1, 8)):
        flips[rng.randrange(len(flips))] = rng.randrange(32, 127)
    return [
        ("route-twice", ring.replace(route, route + route, 1), {2}),
        ("link-twice", ring.replace(link, link + link, 1), {2}),
        ("host-twice", ring.replace(host, host + host, 1), {2}),
        (f"element-{elem}", cube.replace("  </zone>\n</platform>",
                                         f'    <{elem} id="x" host="node0"/>\n  </zone>\n</platform>'),
         {2}),
        (f"host-{attr}", ring.replace("<host id=\"node1\"", f'<host id="node1" {attr}="{value}"', 1),
         {2}),
        (f"cluster-{attr}", cube.replace("<cluster ", f'<cluster {attr}="{value}" ', 1), {2}),
        (f"link-{attr}", cube.replace('<link id="host-up"', f'<link id="host-up" {attr}="{value}"', 1),
         {2}),
        ("sharing-" + (p := rng.choice(["WIFI", "FATPIPE", "bogus", "SHARED"])),
         cube.replace('sharing_policy="SPLITDUPLEX"', f'sharing_policy="{p}"'), {2}),
        ("link-sharing-" + p, ring.replace(link, link.replace("/>", f' sharing_policy="{p}"/>'), 1),
         {0} if p == "SHARED" else {2}),
        (f"nested-{(d := rng.choice([3, 20, 500, 2000]))}", nested_zones(cube, d), {2}),
        ("routing-" + (rt := rng.choice(["Vivaldi", "Wifi", "Cluster", "Full ", "", "ClusterFatTree"])),
         cube.replace('routing="None"', f'routing="{rt}"'), {2}),
        (f"radical-{big}", cube.replace('radical="0-3"', f'radical="{big}"'), {2}),
        ("topo-" + (tp := rng.choice(["2,2,", "99999999999", "0,4", "2,x", "4", "FAT"])),
         cube.replace('topo_parameters="2,2"', f'topo_parameters="{tp}"'), {2}),
        ("cluster-topology-" + (t := rng.choice(["FLAT", "FAT_TREE", "DRAGONFLY", "torus"])),
         cube.replace('topology="TORUS"', f'topology="{t}"'), {2}),
        ("speed-" + (sp := rng.choice(["16Mf,8Mf", "1e400f", "-16Mf", "nanf", "16", "16Mq", "0f"])),
         cube.replace('speed="16Mf"', f'speed="{sp}"'), {2}),
        ("bw-" + (bw := rng.choice(["1e400Bps", "-2MBps", "0Bps", "2.8", "NaNBps", "2.8MBps,1"])),
         cube.replace('bw="2.8MBps"', f'bw="{bw}"'), {2}),
        (f"truncated-at-{cut}", cube[:cut], {2}),
        ("byte-flips", flips.decode(), {0, 1, 2}),
        ("empty", "", {2}),
        ("not-xml", "\x00\x01binary\xff" * 10, {2}),
        ("attribute-twice", cube.replace('<cluster ', '<cluster speed="1Mf" ', 1), {2}),
        ("text-in-zone", cube.replace("  </zone>\n</platform>", "hello\n  </zone>\n</platform>"),
         {2}),
        ("version-" + (v := rng.choice(["3", "4", "5", "abc", "4.10"])),
         cube.replace('version="4.1"', f'version="{v}"'), {2}),
        ("entity", cube.replace("<platform", '<!DOCTYPE x [<!ENTITY a "aaaaaaaaaa">]><platform', 1),
         {0, 2}),
        ("zone-prop-" + (zp := rng.choice(["x", "zcube.cycles", "zcube.nodes"])),
         cube.replace('<prop id="zcube.machine"', f'<prop id="{zp}" value="1"/><prop id="zcube.machine"', 1),
         {2}),
        ("host-prop", ring.replace('<prop id="smpi/or"', '<prop id="wattage_per_state" value="1:2"/><prop id="smpi/or"', 1),
         {2}),
        ("link-ctn-unknown", ring.replace('<link_ctn id="ch-', '<link_ctn id="nope-', 1), {2}),
        ("route-to-nowhere", ring.replace('dst="node1"', 'dst="node9"', 1), {2}),
        ("id-clash", ring.replace('<link id="ch-0-1"', '<link id="node0"', 1)
         .replace('<link_ctn id="ch-0-1"', '<link_ctn id="node0"'), {0, 2}),
    ]


def gen_structure(r, rng, count):
    cube, ring = r.base("ipsc2", 4), r.base("volvox", 4, "ring")
    done = 0
    while done < count:
        for name, xml, want in structure_members(rng, cube, ring):
            if done == count:
                break
            r.run_file(f"structure-{done}-{name}", xml, want)
            done += 1


# --- Figures beyond what a node's memory or the simulated clock can hold: a range error, exit 2.
def gen_overflow(r, rng, count):
    for i in range(count):
        machine = rng.choice([("ipsc2", 4, "cube"), ("volvox", 4, "ring")])
        xml = r.base(*machine)
        prop = rng.choice(["zcube.os_resident", "zcube.node_memory", "zcube.cycles.spans"])
        unit = "" if prop.startswith("zcube.cycles") else rng.choice(["B", "KiB", "TiB", "YiB"])
        value = f"1e{rng.randint(17, 308)}{unit}"
        edited = re.sub(rf'(<prop id="{re.escape(prop)}" value=")[^"]*"', rf'\g<1>{value}"', xml)
        r.run_file(f"overflow-{i}-{prop}-{value}", edited, {2}, ["--nodes", "4"])


# --- A platform written with what-ifs runs as the built-in machine with the same flags, to the bit.
WHATIFS = [("--latency", ["120us", "1ms", "33.3us"]), ("--bandwidth", ["100MBps", "1MBps", "0.5MBps", "3.3MBps"]),
           ("--per-hop", ["1us", "25us"]), ("--host-latency", ["10us", "5ms"]),
           ("--host-bandwidth", ["10MBps", "0.3MBps"]), ("--cpu-scale", ["0.25", "3", "0.7", "1.37", "7.77"]),
           ("--memory", ["64MiB", "3MiB"])]


def virtual_times(r, cmd):
    """The run's virtual time and its phases' times, as the report has them (to the bit)."""
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if p.returncode != 0:
        return f"exit {p.returncode}: {p.stderr.strip()[:200]}"
    with open(cmd[cmd.index("--report") + 1]) as f:
        report = json.load(f)
    return json.dumps([report["virtual_time_s"], report.get("phases")])


def gen_roundtrip(r, rng, count):
    machines = [("ipsc2", "cube", 4), ("ipsc860", "cube", 4), ("volvox", "ring", 6)]
    for i in range(count):
        machine, topo, nodes = machines[i % len(machines)]
        flag, values = WHATIFS[(i // len(machines)) % len(WHATIFS)]
        value = rng.choice(values)
        if flag == "--per-hop" and machine == "volvox":
            flag, value = "--latency", "70us"
        name = f"roundtrip-{machine}{flag}-{value}"
        path = os.path.join(r.tmp, name + ".xml")
        made = subprocess.run([r.zcube, "platform", "--machine", machine, "--topology", topo,
                               "--nodes", str(nodes), flag, value, "-o", path],
                              capture_output=True, text=True)
        r.members += 1
        if made.returncode != 0:
            print(f"ok   {name}: refused: {made.stderr.strip()}")
            continue
        run = [r.zcube, "run", "--scene", os.path.join(r.src, "scenes/kurc/1pot.json"),
               "--size", "128x128",
               "--algorithm",
               rng.choice(["sort-last-folding", "elastic"] + (["pair-rs"] if topo == "cube" else [])),
               "--fidelity", rng.choice(["circuit", "flow", "analytic"])]
        a = virtual_times(r, run + ["--machine", path, "--report", path + ".a.json"])
        b = virtual_times(r, run + ["--machine", machine, "--topology", topo, "--nodes", str(nodes),
                                   flag, value, "--report", path + ".b.json"])
        if a != b or a.startswith("exit"):  # a run that failed is no round trip
            r.wrong += 1
            print(f"FAIL {name} {' '.join(run[4:])}: file {a}, flags {b}")
        else:
            print(f"ok   {name} {' '.join(run[4:])}: {a[:60]}... both ways")


# --- Where standard output is the result, a write that fails is exit 1 with one line.
def gen_stdout(r, rng, count):
    report = os.path.join(r.tmp, "report.json")
    subprocess.run([r.zcube, "run", *SMALL, "--report", report], capture_output=True, check=True)
    commands = [["platform", "--machine", "ipsc2", "--nodes", "4"],
                ["platform", "--machine", "volvox", "--topology", "ring", "--nodes", "64"],
                ["units", "--json"], ["units"], ["pingpong"], ["run", "--list"], ["--version"],
                ["compare", "--measured", report, "--predicted", report],
                ["run", "--size", "16x16"], ["--help"], ["run", "--help"]]
    with open("/dev/full", "w") as full:
        for i in range(count):
            c = commands[i % len(commands)]
            r.check(f"stdout-full-{i}: zcube {' '.join(c[:3])}", [r.zcube, *c], {1}, stdout=full)


# --- An output that is a FIFO is refused before any work (opening it would wait for a reader).
def output_cases(r, path):
    scene = ["--scene", os.path.join(r.src, "scenes/kurc/1pot.json")]
    img = path + ".png"
    return [(["run", *scene, *SMALL, "--image", img], img), (["run", *scene, *SMALL, "--depth", path + ".exr"], path + ".exr"),
            (["run", *scene, *SMALL, "--report", path + ".json"], path + ".json"),
            (["run", *scene, *SMALL, "--trace", path + ".trace.json"], path + ".trace.json"),
            (["run", *scene, *SMALL, "--gantt", path + ".gantt.png"], path + ".gantt.png"),
            (["platform", "--machine", "ipsc2", "-o", path + ".xml"], path + ".xml"),
            (["render", *scene, *SMALL, "--image", path + ".r.png"], path + ".r.png")]


def gen_fifo(r, rng, count):
    for i in range(count):
        base = os.path.join(r.tmp, f"fifo{i}")
        args, out = rng.choice(output_cases(r, base))
        if not os.path.exists(out):
            os.mkfifo(out)
        r.check(f"fifo-{i}: zcube {args[0]} ... {os.path.basename(out)}", [r.zcube, *args], {2},
                named=os.path.basename(out), timeout=20)


# --- An output through a link to a full device: the failed write is exit 1, never lost.
def gen_device(r, rng, count):
    if not os.access("/dev/full", os.W_OK):
        print("skip: no writable /dev/full")
        return
    for i in range(count):
        base = os.path.join(r.tmp, f"dev{i}")
        args, out = rng.choice(output_cases(r, base))
        if not os.path.lexists(out):
            os.symlink("/dev/full", out)
        r.check(f"device-{i}: zcube {args[0]} ... {os.path.basename(out)} -> /dev/full",
                [r.zcube, *args], {1}, named=os.path.basename(out))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("zcube")
    ap.add_argument("src")
    ap.add_argument("cls", choices=["config", "structure", "overflow", "roundtrip", "stdout",
                                    "fifo", "device"])
    ap.add_argument("--count", type=int, default=12)
    ap.add_argument("--seed", type=int, default=None)
    a = ap.parse_args()
    seed = a.seed if a.seed is not None else random.randrange(1 << 30)
    print(f"class {a.cls}: {a.count} members, seed {seed}")
    with tempfile.TemporaryDirectory(prefix="zcube-hostile-") as tmp:
        r = Runner(os.path.abspath(a.zcube), os.path.abspath(a.src), tmp)
        globals()["gen_" + a.cls](r, random.Random(seed), a.count)
    print(f"class {a.cls}: {r.members} members, {r.wrong} wrong (seed {seed})")
    return 1 if r.wrong else 0


if __name__ == "__main__":
    sys.exit(main())
