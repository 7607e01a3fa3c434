#!/usr/bin/env python3
"""systemd's notify and watchdog protocol, spoken by a real service process to
a socket this test owns (as systemd would own it for a Type=notify unit with
WatchdogSec=):

  1. the map_publisher sends READY=1 once its endpoints exist, with a STATUS=
     naming them;
  2. it sends WATCHDOG=1 steadily while idle and while scans flow;
  3. a real hang stops the pings: the map is saved through a path that is a
     FIFO nobody reads (like a write to a stuck disk or network mount), so the
     service loop blocks in open() holding the map, and the reader's worker
     blocks behind it; no test hook in the service;
  4. once the FIFO is read (the write completes), the pings resume;
  5. SIGTERM: STOPPING=1, exit 0;
  6. a jump_filter holding for a reader that is gone (required_readers 1,
     no penetration_filter) keeps pinging: a hold is a deliberate wait, not
     a hang, and the watchdog must not kill a stage with a scan in its hands.

The pipeline feeding it (scan_ingest -> jump_filter -> penetration_filter) is
the build tree's real services. Runs in a private network namespace when it
can (as tests/dds/pipeline_test.sh does).

  notify_watchdog_test.py BUILD_DIR SOURCE_DIR
"""
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.request

BUILD, SRC = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])

if not os.environ.get("SCANFILTER_IN_NETNS") and shutil.which("unshare"):
    unshare = ["unshare", "-n"] if os.getuid() == 0 else ["unshare", "-r", "-n"]
    if subprocess.run(unshare + ["true"], stderr=subprocess.DEVNULL).returncode == 0:
        os.execvp("unshare", unshare + ["env", "SCANFILTER_IN_NETNS=1", "bash", "-c",
                                        'ip link set lo up && exec python3 "$0" "$@"', __file__] + sys.argv[1:])

# WatchdogSec of the simulated unit. The service pings every quarter of it and
# stops once a worker is older than half of it (systemd_notifier.cpp); 3 s
# leaves a loaded machine's scheduling delays far below 1.5 s.
WATCHDOG_S = 3.0
# Bounds on waiting for something that should happen (loaded machine).
READY_TIMEOUT_S = 30.0
FEED_TIMEOUT_S = 60.0
DOMAIN = 0 if os.environ.get("SCANFILTER_IN_NETNS") else 10 + os.getpid() % 200

work = tempfile.mkdtemp(prefix="notify_test.")
processes = []


def fail(message):
    print(f"FAIL: {message}")
    for name in sorted(os.listdir(work)):
        if name.endswith(".log"):
            with open(os.path.join(work, name), errors="replace") as f:
                print(f"--- {name}\n" + "".join(f.readlines()[-20:]))
    sys.exit(1)


def cleanup():
    for p in processes:
        if p.poll() is None:
            p.kill()
            p.wait()
    shutil.rmtree(work, ignore_errors=True)


class NotifySocket:
    """The AF_UNIX datagram socket systemd listens on; every message with its arrival time."""

    def __init__(self, path):
        self.path = path
        self.sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
        self.sock.bind(path)
        self.sock.settimeout(0.2)
        self.messages = []  # (monotonic time, "KEY=value")
        self.lock = threading.Lock()
        self.closed = False
        self.thread = threading.Thread(target=self._receive, daemon=True)
        self.thread.start()

    def _receive(self):
        while not self.closed:
            try:
                data = self.sock.recv(4096)
            except socket.timeout:
                continue
            now = time.monotonic()
            with self.lock:
                for line in data.decode().splitlines():
                    self.messages.append((now, line))

    def times_of(self, line, since=0.0):
        with self.lock:
            return [t for t, m in self.messages if m == line and t >= since]

    def lines_starting(self, prefix):
        with self.lock:
            return [m for _, m in self.messages if m.startswith(prefix)]

    def wait_for(self, line, timeout_s, since=0.0, until_exit=None):
        """The arrival time of `line` (after `since`); None after timeout_s or once until_exit has exited."""
        deadline = time.monotonic() + timeout_s
        while time.monotonic() < deadline:
            times = self.times_of(line, since)
            if times:
                return times[0]
            if until_exit is not None and until_exit.poll() is not None:
                return None
            time.sleep(0.05)
        return None


def start(name, argv, env=None):
    log = open(os.path.join(work, name + ".log"), "w")
    p = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=env)
    processes.append(p)
    return p


def write(name, text):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def metrics_page(port):
    try:
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/metrics", timeout=2) as r:
            return r.read().decode()
    except OSError:
        return ""


def largest_gap(times, start, end):
    points = [start] + [t for t in times if start <= t <= end] + [end]
    return max(b - a for a, b in zip(points, points[1:]))


def main():
    profiles = os.path.join(SRC, "deploy", "fastdds-loopback.xml")
    scans = os.path.join(work, "in.scanlog.jsonl")
    subprocess.run([os.path.join(BUILD, "tools", "scanfilter"), "simulate", "--scene", "hall", "--seed", "3",
                    "--max-frames", "40", "-o", scans], check=True, stdout=subprocess.DEVNULL)
    map_base = os.path.join(work, "map")
    map_config = write("map_publisher.yaml", f"""
service: {{domain_id: {DOMAIN}, profiles_file: {profiles}, metrics_address: 127.0.0.1:19474}}
publishing: {{rate_hz: 5.0, save_path: {map_base}, save_period_s: 0.2}}
""")
    notify = NotifySocket(os.path.join(work, "notify.sock"))
    env = dict(os.environ, NOTIFY_SOCKET=notify.path, WATCHDOG_USEC=str(int(WATCHDOG_S * 1e6)))
    # WATCHDOG_PID as systemd sets it: the service's own PID (a shell execs it).
    service = start("map_publisher", ["sh", "-c", 'WATCHDOG_PID=$$ exec "$0" "$@"',
                                      os.path.join(BUILD, "services", "map_publisher"), "--config", map_config], env)
    started = time.monotonic()

    # 1. READY=1, with the endpoints in its status, and the service answering.
    ready = notify.wait_for("READY=1", READY_TIMEOUT_S, until_exit=service)
    if ready is None:
        fail(f"no READY=1 within {READY_TIMEOUT_S} s (exit status {service.poll()})")
    status = notify.lines_starting("STATUS=started:")
    if not status or "rt/labeled_scan -> rt/map and rt/map_updates" not in status[0]:
        fail(f"READY=1 without the endpoints in its STATUS: {status}")
    if "scanfilter_" not in metrics_page(19474):
        fail("READY=1 sent but the metrics endpoint does not answer")
    print(f"READY=1 {ready - started:.2f} s after start: {status[0]}")

    # 2. Pings while idle: at least every half interval.
    time.sleep(2 * WATCHDOG_S)
    now = time.monotonic()
    idle_pings = notify.times_of("WATCHDOG=1", ready)
    gap = largest_gap(idle_pings, ready, now)
    if len(idle_pings) < 4 or gap > WATCHDOG_S / 2:
        fail(f"idle: {len(idle_pings)} WATCHDOG=1 in {now - ready:.1f} s, largest gap {gap:.2f} s")
    print(f"idle: {len(idle_pings)} WATCHDOG=1 in {now - ready:.1f} s, largest gap {gap:.2f} s")

    # 3. The hang: the next save's temporary file is a FIFO with no reader.
    fifo = map_base + ".pgm.tmp"
    os.mkfifo(fifo)
    start("penetration_filter", [os.path.join(BUILD, "services", "penetration_filter"), "--domain", str(DOMAIN),
                                 "--metrics-address", "127.0.0.1:19473"])
    start("jump_filter", [os.path.join(BUILD, "services", "jump_filter"), "--domain", str(DOMAIN),
                          "--metrics-address", "127.0.0.1:19472"])
    ingest_config = write("scan_ingest.yaml", f"""
service: {{domain_id: {DOMAIN}, profiles_file: {profiles}, metrics_address: 127.0.0.1:19471}}
source: {{kind: log, path: {scans}, rate: recorded}}
playback: {{wait_for_subscribers: 1, wait_timeout_s: 30, exit_at_end: true}}
""")
    feed_start = time.monotonic()
    start("scan_ingest", [os.path.join(BUILD, "services", "scan_ingest"), "--config", ingest_config])
    deadline = feed_start + FEED_TIMEOUT_S
    stalled_at = None
    while time.monotonic() < deadline and stalled_at is None:
        pings = notify.times_of("WATCHDOG=1", feed_start)
        last = pings[-1] if pings else feed_start
        if time.monotonic() - last > 2 * WATCHDOG_S:
            stalled_at = last
        if service.poll() is not None:
            fail(f"map_publisher exited ({service.returncode}) instead of hanging")
        time.sleep(0.1)
    if stalled_at is None:
        fail(f"WATCHDOG=1 never stopped within {FEED_TIMEOUT_S} s of feeding scans into a save that blocks")
    stalled_status = notify.lines_starting("STATUS=stalled:")
    if not stalled_status:
        fail("the pings stopped without a STATUS=stalled: line")
    pings_before = [t for t in notify.times_of("WATCHDOG=1", feed_start) if t <= stalled_at]
    print(f"hang: {len(pings_before)} WATCHDOG=1 while scans flowed, then none for > {2 * WATCHDOG_S:.0f} s; "
          f"{stalled_status[0]}")

    # 4. Unblock the write: the pings resume.
    drained = bytearray()

    def drain():
        with open(fifo, "rb") as f:
            drained.extend(f.read())

    reader = threading.Thread(target=drain, daemon=True)
    unblocked = time.monotonic()
    reader.start()
    resumed = notify.wait_for("WATCHDOG=1", 4 * WATCHDOG_S, since=unblocked)
    if resumed is None:
        fail("no WATCHDOG=1 after the blocked save was unblocked")
    reader.join(timeout=10)
    if not drained.startswith(b"P5\n"):
        fail(f"the blocked write was not the map's PGM: {bytes(drained[:16])!r}")
    print(f"unblocked: the save wrote a {len(drained)}-byte PGM; WATCHDOG=1 again after {resumed - unblocked:.2f} s")

    # 5. A clean stop.
    stop_requested = time.monotonic()
    service.terminate()
    try:
        code = service.wait(timeout=30)
    except subprocess.TimeoutExpired:
        fail("map_publisher did not stop within 30 s of SIGTERM")
    if code != 0:
        fail(f"map_publisher exited {code} after SIGTERM")
    if notify.wait_for("STOPPING=1", 2, since=stop_requested) is None:
        fail("no STOPPING=1 on SIGTERM")
    notify.closed = True
    print("SIGTERM: STOPPING=1, exit 0")
    holding_stage_keeps_pinging(profiles, scans)
    print("PASS")


def holding_stage_keeps_pinging(profiles, scans):
    domain = DOMAIN + 1  # away from the first part's services, still running
    notify = NotifySocket(os.path.join(work, "notify_jump.sock"))
    env = dict(os.environ, NOTIFY_SOCKET=notify.path, WATCHDOG_USEC=str(int(WATCHDOG_S * 1e6)))
    jump_config = write("jump_hold.yaml", f"""
service: {{domain_id: {domain}, profiles_file: {profiles}, metrics_address: 127.0.0.1:19482, required_readers: 1}}
filter: {{config: {os.path.join(SRC, "config", "filter.yaml")}}}
""")
    jump = start("jump_hold", ["sh", "-c", 'WATCHDOG_PID=$$ exec "$0" "$@"',
                               os.path.join(BUILD, "services", "jump_filter"), "--config", jump_config], env)
    if notify.wait_for("READY=1", READY_TIMEOUT_S, until_exit=jump) is None:
        fail(f"the holding jump_filter sent no READY=1 (exit status {jump.poll()})")
    ingest_config = write("scan_ingest_hold.yaml", f"""
service: {{domain_id: {domain}, profiles_file: {profiles}, metrics_address: 127.0.0.1:19481}}
source: {{kind: log, path: {scans}, rate: max}}
playback: {{wait_for_subscribers: 1, wait_timeout_s: 30, exit_at_end: true}}
""")
    start("scan_ingest_hold", [os.path.join(BUILD, "services", "scan_ingest"), "--config", ingest_config])
    log_path = os.path.join(work, "jump_hold.log")
    deadline = time.monotonic() + FEED_TIMEOUT_S
    holding_since = None
    while holding_since is None and time.monotonic() < deadline:
        with open(log_path, errors="replace") as f:
            if "holding rt/jump_filtered_scan" in f.read():
                holding_since = time.monotonic()
        time.sleep(0.05)
    if holding_since is None:
        fail(f"the jump_filter without a reader did not hold within {FEED_TIMEOUT_S} s")
    time.sleep(3 * WATCHDOG_S)
    now = time.monotonic()
    pings = notify.times_of("WATCHDOG=1", holding_since)
    gap = largest_gap(pings, holding_since, now)
    if gap > WATCHDOG_S / 2 or notify.lines_starting("STATUS=stalled:"):
        fail(f"holding: largest gap between WATCHDOG=1 {gap:.2f} s; {notify.lines_starting('STATUS=stalled:')}")
    print(f"holding: {len(pings)} WATCHDOG=1 in {now - holding_since:.1f} s of holding, largest gap {gap:.2f} s")
    notify.closed = True


try:
    main()
finally:
    cleanup()
