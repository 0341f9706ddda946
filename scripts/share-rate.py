#!/usr/bin/env python3
"""How many frames a second one shared screen's POSTs are taken at, one in flight as the control
page sends them (control_page/README.md, "Share a screen"): a session run with shares, a share of
the JPEG's size opened over HTTP and the JPEG POSTed for SECONDS, then the share's counts.
Usage: scripts/share-rate.py L2WALL SESSION JPEG WIDTH HEIGHT [SECONDS]"""
import http.client
import json
import re
import shutil
import subprocess
import sys
import tempfile
import time

l2wall, session, jpeg, width, height = sys.argv[1:6]
seconds = float(sys.argv[6]) if len(sys.argv) > 6 else 10
out = tempfile.mkdtemp(prefix="share-rate-")
run = subprocess.Popen([l2wall, "run", "--scene", "session", "--session", session, "--frames",
                        "1000000", "--keep", "none", "--no-progress", "--http", "127.0.0.1:0",
                        "--out", out], stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
try:
    found = None
    while not found:
        line = run.stderr.readline()
        if not line:
            sys.exit("l2wall ended before printing its control page")
        found = re.search(r"http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]+)", line)
    port, token = int(found.group(1)), found.group(2)
    http = http.client.HTTPConnection("127.0.0.1", port)

    def post(path, body=b""):
        http.request("POST", f"{path}&token={token}", body, {"Content-Type": "image/jpeg"})
        answer = http.getresponse()
        return answer.status, json.loads(answer.read())

    for _ in range(100):  # until the run takes requests
        status, answer = post(f"/api/share?width={width}&height={height}&name=rate")
        if status != 503:
            break
    if status != 200:
        sys.exit(f"not shared: {answer}")
    window = int(re.search(r" as window (\d+) \(", answer["done"]).group(1))
    frame = open(jpeg, "rb").read()
    taken, start = 0, time.monotonic()
    while time.monotonic() - start < seconds:
        taken += post(f"/api/share/frame?window={window}", frame)[0] == 200
    took = time.monotonic() - start
    time.sleep(0.5)  # the state is published a few times a second
    http.request("GET", "/api/state")
    state = json.loads(http.getresponse().read())
    share = state["shares"]["shown"][0]
    print(f"{taken} frames of {len(frame)} bytes taken in {took:.1f} s: {taken / took:.1f} a second; "
          f"shown {share['shown']}, dropped {share['dropped']}; the run at {state['fps']:.1f} fps")
finally:
    run.terminate()
    run.wait()
    shutil.rmtree(out, ignore_errors=True)
