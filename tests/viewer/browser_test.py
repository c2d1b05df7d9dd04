#!/usr/bin/python3
"""The viewer in a real browser (docs/viewer.md#how-it-is-tested): headless Chromium with
SwiftShader's WebGL, driven by Selenium with Debian's chromium-driver.

For every kind of viewer page (each structure with a ray, a pixel of a render, a6's samplers,
the DDA case, the hostile case and the hostile report of viewer_test_cases): the page loads from file:// with no
console error and says it is ready. For every page with a ray: the steps the page lists and
steps through are the trace file's, operation for operation (the trace written by
`rtlab-solution view --trace-out`, decoded here by this file's own reader of the format of
framework/accel/traversal_trace_format.h). Screenshots are checked by their pixels: the hit
marker lies where the hit projects through the page's camera, and the DDA case's cells have the
colours of the walks they belong to. The hostile page runs nothing and shows its markup as text;
so does the hostile grading report, and the viewer its "open in viewer" link opens.

Usage: browser_test.py BUILD_DIR SOURCE_DIR [--screenshots DIR]
  --screenshots DIR also writes the screenshots the docs show (docs/images/viewer-*.png come
  from here: tests/viewer/browser_test.py build . --screenshots docs/images).
"""
import argparse
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import time

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
except ImportError:
    print("browser_test: python3-selenium is missing (scripts/install-deps installs it)")
    sys.exit(1)

OP_NAMES = ["box test", "cell step", "leaf entry", "plane step", "primitive test", "mailbox repeat"]
FOV_DEGREES = 50.0  # the page's camera (viewer/page/viewer.js, makeView)
DDA_OPACITY = 0.6   # the DDA cells over white (viewer.js, DDA_OPACITY)
COLOURS = {"expected": (0x3b, 0x82, 0xf6), "student": (0xef, 0x44, 0x44), "both": (0xa8, 0x55, 0xf7)}
MARKER = (255, 0, 255)
FAILURES = []


def fail(message):
    FAILURES.append(message)
    print("FAIL:", message)


def check(condition, message):
    if not condition:
        fail(message)
    return condition


# --- The trace format (framework/accel/traversal_trace_format.h) ------------------------------
def read_trace(path):
    data = open(path, "rb").read()
    magic, version, zero, ops, boxes, dropped = struct.unpack_from("<IHHIIQ", data, 0)
    assert magic == 0x72745452 and version == 1 and zero == 0, path + ": not a trace"
    assert len(data) == 24 + 16 * ops + 24 * boxes, path + ": wrong size"
    trace = []
    for i in range(ops):
        kind, hit, reserved, index, t, t_far = struct.unpack_from("<BBHIff", data, 24 + 16 * i)
        trace.append({"kind": kind, "hit": hit, "index": index, "t": t})
    return trace


# --- The browser ----------------------------------------------------------------------------------
def start_browser(profile):
    options = webdriver.ChromeOptions()
    for argument in ["--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                     "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
                     "--force-device-scale-factor=1", "--window-size=1400,1000", "--user-data-dir=" + profile]:
        options.add_argument(argument)
    options.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(shutil.which("chromedriver") or "/usr/bin/chromedriver"), options=options)


def open_page(browser, folder, fragment=""):
    """Loads FOLDER/index.html and waits until it says it is ready; returns its console errors."""
    browser.get("about:blank")  # a new document even when only the fragment differs
    browser.get_log("browser")  # forget the previous page's messages
    browser.get("file://" + os.path.abspath(os.path.join(folder, "index.html")) + fragment)
    for _ in range(300):
        state = browser.execute_script("return document.body.dataset.state")
        if state != "loading":
            break
        time.sleep(0.1)
    status = browser.find_element(By.ID, "status").text
    check(state == "ready", f"{folder}: the page is '{state}', not ready: {status}")
    wait_for_frame(browser)
    errors = [e["message"] for e in browser.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    check(not errors, f"{folder}: console errors: {errors}")
    return errors


def wait_for_frame(browser):
    """Until the 3D view has drawn what the last action asked for (it renders on the next frame)."""
    browser.execute_script("return new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")


def screenshot(browser, path):
    browser.save_screenshot(path)
    return read_png(path)


def read_png(path):
    """RGB rows of an 8-bit PNG as Chromium writes it (no library needed: zlib and filters)."""
    import zlib
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    at, idat, width, height, colour = 8, b"", 0, 0, 0
    while at < len(data):
        length, kind = struct.unpack_from(">I4s", data, at)
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack_from(">IIBB", body)
            assert depth == 8 and colour in (2, 6)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    raw = zlib.decompress(idat)
    channels = 3 if colour == 2 else 4
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[i:i + 3]) for i in range(0, stride, channels)])
        previous = line
    return rows


# --- The page's camera, as three.js makes it (a perspective look-at camera, up +y) ---------------
def projector(browser, eye, target):
    rect = browser.execute_script("const r = document.getElementById('view3d').getBoundingClientRect();"
                                  "return [r.left, r.top, r.width, r.height];")
    left, top, width, height = rect
    sub = lambda a, b: [a[i] - b[i] for i in range(3)]
    dot = lambda a, b: sum(a[i] * b[i] for i in range(3))
    cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    norm = lambda a: [v / math.sqrt(dot(a, a)) for v in a]
    back = norm(sub(eye, target))            # the camera looks down -back
    right = norm(cross([0, 1, 0], back))
    up = cross(back, right)
    f = 1 / math.tan(math.radians(FOV_DEGREES) / 2)

    def project(p):
        d = sub(p, eye)
        x, y, z = dot(d, right), dot(d, up), -dot(d, back)
        ndc_x, ndc_y = f * x / z / (width / height), f * y / z
        return left + (ndc_x + 1) / 2 * width, top + (1 - ndc_y) / 2 * height
    return project


# --- The checks ----------------------------------------------------------------------------------
def check_steps(browser, name, trace):
    """The page lists the trace's operations in order, and stepping walks through them."""
    listed = browser.execute_script(
        "return Array.from(document.querySelectorAll('#student-steps li[data-kind]')).map(li => [Number(li.dataset.kind), Number(li.dataset.index), li.textContent])")
    check(len(listed) == min(len(trace), 5000), f"{name}: the page lists {len(listed)} steps, the trace has {len(trace)}")
    for k, (op, item) in enumerate(zip(trace, listed)):
        if not check(item[0] == op["kind"] and item[1] == op["index"] and item[2].startswith(OP_NAMES[op["kind"]]),
                     f"{name}: step {k} is '{item[2]}' on the page, {OP_NAMES[op['kind']]} {op['index']} in the trace"):
            return
    browser.find_element(By.ID, "step-first").click()
    for k in range(min(len(trace), 60)):
        step = browser.execute_script("return Number(document.body.dataset.step)")
        current = browser.find_element(By.ID, "step-current").text
        check(step == k and f"step {k}: {OP_NAMES[trace[k]['kind']]}" in current,
              f"{name}: after {k} steps forward the page is at {step}: '{current}'")
        browser.find_element(By.ID, "step-next").click()
    browser.find_element(By.ID, "step-prev").click()
    check(browser.execute_script("return Number(document.body.dataset.step)") == max(0, min(len(trace), 60) - 1), f"{name}: a step back")


def check_hit_marker(browser, folder, name, ray, hit_t, shots):
    o, d = ray[:3], ray[3:6]
    hit = [o[i] + hit_t * d[i] for i in range(3)]
    eye = [hit[0] + 1.7, hit[1] + 1.1, hit[2] + 2.9]
    fragment = "#camera=" + ",".join(f"{v:.6g}" for v in eye + hit) + "&mesh=hidden&structure=off"
    open_page(browser, folder, fragment)
    browser.find_element(By.ID, "step-last").click()
    wait_for_frame(browser)
    rows = screenshot(browser, os.path.join(shots, name + "-hit.png"))
    x, y = projector(browser, eye, hit)(hit)
    marked = [(px, py) for py, row in enumerate(rows) for px, c in enumerate(row) if c == MARKER]
    if check(marked, f"{name}: no hit marker in the screenshot"):
        cx = sum(p[0] for p in marked) / len(marked)
        cy = sum(p[1] for p in marked) / len(marked)
        check(abs(cx - x) <= 2.5 and abs(cy - y) <= 2.5,
              f"{name}: the hit marker is at ({cx:.1f}, {cy:.1f}), the hit projects to ({x:.1f}, {y:.1f})")


def check_dda(browser, folder, cells, shots):
    eye, target = [4, 3, 13], [4, 3, 0.5]
    open_page(browser, folder, "#camera=" + ",".join(map(str, eye + target)))
    rows = screenshot(browser, os.path.join(shots, "dda.png"))
    project = projector(browser, eye, target)
    blend = {k: tuple(round(DDA_OPACITY * c + (1 - DDA_OPACITY) * 255) for c in v) for k, v in COLOURS.items()}
    blend["none"] = (255, 255, 255)
    expected = {tuple(c) for c in cells["expected"]}
    student = {tuple(c) for c in cells["student"]}
    check(expected - student and student - expected and expected & student, "the DDA case has no cells of each kind")
    for cx in range(8):
        for cy in range(6):
            cell = (cx, cy, 0)
            kind = "both" if cell in expected and cell in student else "expected" if cell in expected else "student" if cell in student else "none"
            # Four points inside the cell: the ray's line may cross one of them.
            seen = []
            # (Near the centre: the grid's far outline and the cells' sides show nearer the edges.)
            for dx, dy in [(-0.1, -0.1), (0.1, -0.1), (-0.1, 0.1), (0.1, 0.1)]:
                x, y = project([cx + 0.5 + dx, cy + 0.5 + dy, 0.92])
                seen.append(rows[round(y)][round(x)])
            right = [c for c in seen if max(abs(c[i] - blend[kind][i]) for i in range(3)) <= 6]
            check(len(right) >= 2, f"DDA cell {cell}: the screenshot shows {seen} in it, {kind} is {blend[kind]}")


def check_hostile(browser, folder, shots):
    open_page(browser, folder)
    browser.find_element(By.ID, "step-last").click()
    browser.find_element(By.ID, "step-first").click()
    wait_for_frame(browser)
    screenshot(browser, os.path.join(shots, "hostile.png"))
    check(browser.execute_script("return window.__pwned === undefined"), "hostile: a script from the data ran")
    check(browser.execute_script("return document.getElementById('injected') === null && document.querySelectorAll('img').length === 0"),
          "hostile: markup from the data became elements")
    title = browser.find_element(By.ID, "title").text
    check(title.startswith("</script><script>window.__pwned=1</script><img src=x"), f"hostile: the title is not shown as text: {title!r}")
    check("onerror" in browser.find_element(By.ID, "notes").text, "hostile: the notes are not shown as text")
    errors = [e["message"] for e in browser.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    check(not errors, f"hostile: console errors (a blocked script would say so): {errors}")


def check_report(browser, folder, passing, shots):
    """The hostile report (viewer_test_cases): its markup shows as text and runs nothing, and its
    one failing case's "open in viewer" link opens a viewer that runs nothing either. A passing
    report writes no viewer data."""
    check(not os.path.exists(os.path.join(passing, "viewer")), "a passing report wrote viewer data")
    browser.get("about:blank")
    browser.get_log("browser")
    browser.get("file://" + os.path.abspath(os.path.join(folder, "index.html")))
    screenshot(browser, os.path.join(shots, "report.png"))
    check(browser.execute_script("return window.__pwned === undefined"), "report: a script from the data ran")
    check(browser.execute_script("return document.getElementById('injected') === null && document.querySelectorAll('img, textarea').length === 0"),
          "report: markup from the data became elements")
    links = browser.find_elements(By.LINK_TEXT, "open in viewer")
    check(len(links) == 1, f"report: {len(links)} 'open in viewer' links, expected 1 (one failing case)")
    hrefs = [a.get_attribute("href") for a in browser.find_elements(By.TAG_NAME, "a")]
    check(not any(h and h.startswith("javascript:") for h in hrefs), f"report: a javascript: link from the data: {hrefs}")
    errors = [e["message"] for e in browser.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    check(not errors, f"report: console errors: {errors}")
    if not links:
        return
    links[0].click()
    for _ in range(300):
        if browser.execute_script("return document.body && document.body.dataset.state") not in (None, "loading"):
            break
        time.sleep(0.1)
    check(browser.execute_script("return document.body.dataset.state") == "ready", "report: the linked viewer is not ready")
    wait_for_frame(browser)
    screenshot(browser, os.path.join(shots, "report-viewer.png"))
    check(browser.execute_script("return window.__pwned === undefined"), "report's viewer: a script from the data ran")
    check(browser.execute_script("return document.getElementById('injected') === null"), "report's viewer: markup from the data became elements")
    check("</textarea>" in browser.find_element(By.ID, "title").text, "report's viewer: the title is not shown as text")
    errors = [e["message"] for e in browser.get_log("browser") if e["level"] in ("SEVERE", "ERROR")]
    check(not errors, f"report's viewer: console errors: {errors}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("source")
    parser.add_argument("--screenshots", help="write the docs' screenshots (viewer-*.png) here too")
    args = parser.parse_args()
    build, source = os.path.abspath(args.build), os.path.abspath(args.source)
    out = os.path.join(build, "test-output", "viewer-browser")
    shutil.rmtree(out, ignore_errors=True)
    shots = os.path.join(out, "screenshots")
    os.makedirs(shots)
    solution, student = os.path.join(build, "rtlab-solution"), os.path.join(build, "rtlab")
    cornell = os.path.join(source, "scenes", "cornell-box.gltf")
    ray = [0.13, 1.17, 3.5, 0.031, -0.107, -1.0]
    ray_text = " ".join(map(str, ray))
    with open(os.path.join(out, "one.rays"), "w") as f:
        f.write(ray_text + "\n")

    def run(*command):
        result = subprocess.run(list(command), capture_output=True, text=True)
        if result.returncode != 0:
            fail(" ".join(command) + f": exit {result.returncode}: {result.stderr.strip()}")
        return result

    pages = {}
    for accel in ["brute", "bvh", "grid", "grid2", "octree", "kdtree", "bsp"]:
        folder = os.path.join(out, accel)
        run(solution, "view", cornell, "--accel", accel, "--ray", ray_text, "-o", folder)
        run(solution, "view", cornell, "--accel", accel, "--rays", os.path.join(out, "one.rays"), "--trace-out", folder + "-trace")
        pages[accel] = (folder, read_trace(os.path.join(folder + "-trace", "trace-0.bin")))
    # The student's rtlab on the same ray: its a0 stub stops the walk; rtlab-solution's walk is beside it.
    run(student, "view", cornell, "--accel", "brute", "--ray", ray_text, "-o", os.path.join(out, "student"))
    run(solution, "view", cornell, "--accel", "bvh", "--pixel", "150,110", "-o", os.path.join(out, "pixel"))
    run(solution, "view", "--samplers", "-o", os.path.join(out, "samplers"))
    cases = run(os.path.join(build, "tests", "viewer_test_cases"), os.path.join(out, "cases"), source)
    dda_cells = json.loads(cases.stdout) if cases.returncode == 0 else None

    # Scale (docs/viewer.md#scale): the bunny's folder at most 2 MB, the sphereflake's at most
    # 64 MB, and a viewer of the engine written in at most 2 s beyond loading and building.
    bunny, engine = os.path.join(build, "models", "bunny.gltf"), os.path.join(build, "models", "engine.glb")
    folder_bytes = lambda d: sum(os.path.getsize(os.path.join(d, f)) for f in os.listdir(d))
    for accel in ["bvh", "grid", "kdtree"]:
        folder = os.path.join(out, "bunny-" + accel)
        run(solution, "view", bunny, "--accel", accel, "--ray", "0 5 24 0.01 0.02 -1", "-o", folder)
        check(os.path.isdir(folder) and folder_bytes(folder) <= 2_000_000, f"the bunny's {accel} viewer is larger than 2 MB")
    for accel in ["bvh", "grid"]:
        result = run(solution, "view", engine, "--accel", accel, "--ray", "0 0 500 0.01 0.02 -1", "-o", os.path.join(out, "engine-" + accel))
        rest = float(result.stdout.split("the rest ")[1].split(" s")[0]) if "the rest " in result.stdout else 99
        check(rest <= 2.0, f"the engine's {accel} viewer took {rest} s beyond loading and building")
    sphereflake = os.path.join(out, "sphereflake.glb")
    run(solution, "scene", "generate", "sphereflake", "-o", sphereflake)
    run(solution, "view", sphereflake, "--accel", "bvh", "--ray", "0 0 5 0.01 0.02 -1", "-o", os.path.join(out, "sphereflake"))
    check(folder_bytes(os.path.join(out, "sphereflake")) <= 64_000_000, "the sphereflake's viewer is larger than 64 MB")

    profile = tempfile.mkdtemp(prefix="rtlab-viewer-chromium-")
    browser = start_browser(profile)
    try:
        version = browser.execute_script(
            "const g = document.createElement('canvas').getContext('webgl2'); return g ? g.getParameter(g.VERSION) : 'none'")
        print("WebGL:", version)
        for accel, (folder, trace) in pages.items():
            open_page(browser, folder, "#depth=2")
            screenshot(browser, os.path.join(shots, accel + ".png"))
            check_steps(browser, accel, trace)
            if accel == "bvh":
                # Hovering a box shows the node's numbers (a2's SAH share among them).
                canvas = browser.find_element(By.ID, "view3d")
                from selenium.webdriver.common.action_chains import ActionChains
                ActionChains(browser).move_to_element_with_offset(canvas, 20, 40).perform()
                wait_for_frame(browser)
                hover = browser.find_element(By.ID, "hover").text
                check("SAH share" in hover, f"bvh: hovering a box does not show its SAH share: {hover!r}")
                screenshot(browser, os.path.join(shots, "bvh-hover.png"))
            hits = [op for op in trace if op["kind"] == 4 and op["hit"]]
            if accel == "bvh" and check(hits, "bvh: the trace has no hit"):
                check_hit_marker(browser, folder, accel, ray, hits[-1]["t"], shots)
        # The sphereflake opens, draws its million triangles and orbits under a drag.
        started = time.time()
        open_page(browser, os.path.join(out, "sphereflake"), "#mesh=solid")
        check(browser.execute_script("return document.body.dataset.triangles") == "1062864", "sphereflake: not every triangle is drawn")
        frames = int(browser.execute_script("return document.body.dataset.frames"))
        from selenium.webdriver.common.action_chains import ActionChains
        canvas = browser.find_element(By.ID, "view3d")
        ActionChains(browser).move_to_element(canvas).click_and_hold().move_by_offset(120, 40).release().perform()
        wait_for_frame(browser)
        check(int(browser.execute_script("return document.body.dataset.frames")) > frames, "sphereflake: a drag does not orbit")
        print(f"sphereflake: opened and orbited in {time.time() - started:.1f} s")
        screenshot(browser, os.path.join(shots, "sphereflake.png"))
        open_page(browser, os.path.join(out, "student"))
        check("a0 intersectTriangle" in browser.find_element(By.ID, "notes").text, "student: the stub that stopped the walk is not named")
        check(browser.execute_script("return document.querySelectorAll('#expected-steps li[data-kind]').length") > 0,
              "student: no reference steps beside the student's")
        screenshot(browser, os.path.join(shots, "student.png"))
        open_page(browser, os.path.join(out, "pixel"))
        check(browser.execute_script("return document.body.dataset.pixel") == "150,110", "pixel: the selected pixel is not loaded")
        browser.execute_script("document.querySelector('img[data-image=heat]').scrollIntoView()")
        image = browser.find_element(By.CSS_SELECTOR, "img[data-image=render]")
        browser.execute_script("const i = arguments[0], r = i.getBoundingClientRect();"
                               "i.dispatchEvent(new MouseEvent('click', {clientX: r.left + i.clientLeft + 160.5, clientY: r.top + i.clientTop + 180.5, bubbles: true}))",
                               image)
        check(browser.execute_script("return document.body.dataset.pixel") == "160,180", "pixel: a click does not load its pixel")
        info = browser.find_element(By.ID, "pixel-info").text
        check("shadow ray to light 0" in info, f"pixel: no shadow ray for a clicked pixel: {info!r}")
        wait_for_frame(browser)
        screenshot(browser, os.path.join(shots, "pixel.png"))
        open_page(browser, os.path.join(out, "samplers"))
        cards = browser.execute_script("return Array.from(document.querySelectorAll('#samplers .card')).map(c => c.textContent)")
        check(len(cards) == 6 and all("p = " in c for c in cards), f"samplers: {len(cards)} cards, not 6 with a p-value")
        screenshot(browser, os.path.join(shots, "samplers.png"))
        if dda_cells:
            check_dda(browser, os.path.join(out, "cases", "dda"), dda_cells, shots)
            check_hostile(browser, os.path.join(out, "cases", "hostile"), shots)
            check_report(browser, os.path.join(out, "cases", "report"), os.path.join(out, "cases", "passing"), shots)
    finally:
        browser.quit()
        shutil.rmtree(profile, ignore_errors=True)

    if args.screenshots:
        for name in ["brute", "bvh", "bvh-hover", "grid", "octree", "kdtree", "bsp", "pixel", "samplers", "dda", "sphereflake"]:
            shutil.copy(os.path.join(shots, name + ".png"), os.path.join(args.screenshots, "viewer-" + name + ".png"))
    print(f"browser_test: {len(FAILURES)} failure(s); screenshots in {shots}")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
