#!/usr/bin/env python3
"""The studio in a real browser: Debian's chromium, headless, driven by selenium.

studio_browser_test.py SHAPEPROC DATA_DIR SCREENSHOT

Starts `shapeproc studio` on two-kinds.svg, waits for the fit, drags the first gamma bar of
pair 0 up, checks that the preview and its verdicts were recomputed, raises it again with the
keyboard, undoes and redoes, exports, and checks that the
exported model holds the new gamma and that `shapeproc sample` makes the exported output again,
byte for byte after its record. Then: a request without the token and a malformed edit are
refused with a clear error, the studio still answers, and Ctrl-C stops it cleanly.
"""
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def start_studio(shapeproc, exemplar, exports):
    process = subprocess.Popen(
        [shapeproc, "studio", exemplar, "--category-by", "fill", "--export-dir", exports,
         "--seed", "3", "--final-seconds", "120"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = process.stdout.readline()
    match = re.search(r"(http://127\.0\.0\.1:\d+/\?token=[0-9a-f]+)", line)
    if not match:
        process.kill()
        fail("studio printed no address: " + line + process.stderr.read())
    return process, match.group(1)


def browser():
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--window-size=1500,1100"):
        options.add_argument(flag)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


def request(url, body=None, headers=None):
    data = None if body is None else body.encode()
    req = urllib.request.Request(url, data=data, headers=headers or {})
    try:
        with urllib.request.urlopen(req, timeout=30) as answer:
            return answer.status, answer.read().decode()
    except urllib.error.HTTPError as error:
        return error.code, error.read().decode()


def after_metadata(path):
    text = open(path, encoding="utf-8").read()
    return text[text.index("</metadata>"):]


def main():
    shapeproc, data, screenshot = (os.path.abspath(a) for a in sys.argv[1:4])
    exports = tempfile.mkdtemp(prefix="studio-e2e-")
    process, url = start_studio(shapeproc, os.path.join(data, "svg", "two-kinds.svg"), exports)
    base, token = url.split("/?token=")
    driver = browser()
    try:
        driver.get(url)
        wait = WebDriverWait(driver, 900, poll_frequency=0.2)
        # 2. The fit, then the first final preview with its verdicts.
        wait.until(lambda d: d.find_element(By.ID, "toolbar").is_displayed())
        preview = driver.find_element(By.ID, "preview")
        wait.until(lambda d: preview.get_attribute("data-stage") == "final")
        first_svg = preview.get_attribute("innerHTML")
        first_revision = int(preview.get_attribute("data-revision"))
        first_verdicts = driver.find_element(By.ID, "verdicts").get_attribute("data-sequence")
        if "<path" not in first_svg and "<circle" not in first_svg:
            fail("the first preview shows no element")
        state = json.loads(request(base + "/api/state", headers={"X-Studio-Token": token})[1])
        fitted_gamma = state["model"]["pairs"][0]["axes"][0]["gammas"][0]
        # 3. Drag the first gamma bar of pair 0 up.
        handle = driver.find_element(By.ID, "gamma-0-0-0")
        ActionChains(driver).click_and_hold(handle).move_by_offset(0, -35).release().perform()
        # 4. A new revision, previewed and judged again.
        wait.until(lambda d: int(preview.get_attribute("data-revision")) > first_revision and
                   preview.get_attribute("data-stage") == "final")
        if preview.get_attribute("innerHTML") == first_svg:
            fail("the preview did not change after the edit")
        verdicts = driver.find_element(By.ID, "verdicts")
        if verdicts.get_attribute("data-sequence") == first_verdicts:
            fail("the verdicts were not recomputed")
        if verdicts.get_attribute("data-sequence") != preview.get_attribute("data-sequence"):
            fail("the verdicts are not the new preview's")
        if len(verdicts.find_elements(By.CSS_SELECTOR, "tbody tr")) < 4:
            fail("fewer than four verdicts shown")
        edits = driver.find_element(By.ID, "edits").text
        if "gamma 0:0:1=" not in edits:
            fail("the edit is not listed: " + edits)
        # The keyboard: a focused handle's Up arrow raises γ by a quarter, and focus stays.
        revision = int(preview.get_attribute("data-revision"))
        driver.execute_script("arguments[0].focus()", driver.find_element(By.ID, "gamma-0-0-0"))
        driver.switch_to.active_element.send_keys(Keys.ARROW_UP)
        wait.until(lambda d: int(preview.get_attribute("data-revision")) > revision and
                   preview.get_attribute("data-stage") == "final")
        if driver.switch_to.active_element.get_attribute("id") != "gamma-0-0-0":
            fail("the keyboard edit lost the handle's focus")
        # Undo and redo: the edit list follows.
        for button, count in (("undo", 1), ("redo", 2)):
            revision = int(preview.get_attribute("data-revision"))
            driver.find_element(By.ID, button).click()
            WebDriverWait(driver, 60).until(
                lambda d: int(preview.get_attribute("data-revision")) > revision and
                len(d.find_elements(By.CSS_SELECTOR, "#edits li")) == count,
                f"after {button}, the preview and a list of {count} edits")
        wait.until(lambda d: preview.get_attribute("data-stage") == "final")
        # The whole page in one picture, from its top.
        height = driver.execute_script("return document.documentElement.scrollHeight")
        driver.set_window_size(1500, min(max(height, 900), 2400))
        driver.execute_script("window.scrollTo(0, 0)")
        time.sleep(0.5)
        driver.save_screenshot(screenshot)
        # 5. Export.
        name = driver.find_element(By.ID, "export-name")
        name.clear()
        name.send_keys("e2e")
        driver.find_element(By.ID, "export").click()
        wait.until(lambda d: d.find_element(By.ID, "exported").text.startswith("wrote"))
        # 6. The exported model's gamma, and `sample` makes its output again.
        model = json.load(open(os.path.join(exports, "e2e.json")))
        gamma = model["interaction"][0]["axes"][0]["gammas"][0]
        if not gamma > fitted_gamma:
            fail(f"the exported gamma {gamma} is not above the fitted {fitted_gamma}")
        command = open(os.path.join(exports, "e2e.sh")).read().strip().splitlines()[-1].split()
        if command[:2] != ["shapeproc", "sample"]:
            fail("unexpected command: " + " ".join(command))
        again = command[:]
        again[0] = shapeproc
        again[again.index("-o") + 1] = "again.svg"
        subprocess.run(again, cwd=exports, check=True, stdout=subprocess.DEVNULL)
        if after_metadata(os.path.join(exports, "again.svg")) != \
                after_metadata(os.path.join(exports, "e2e.svg")):
            fail("`sample` did not make the exported output again")
        # Refused requests: no token, a malformed edit. The studio still answers.
        status, body = request(base + "/api/state")
        if status != 403 or "token" not in body:
            fail(f"a request without the token got {status}: {body}")
        headers = {"X-Studio-Token": token, "Content-Type": "application/json"}
        status, body = request(base + "/api/edit", '{"kind":"gamma","pair":99,"axis":0,'
                               '"index":0,"value":2}', headers)
        if status != 400 or "no interaction 99" not in body:
            fail(f"a malformed edit got {status}: {body}")
        status, _ = request(base + "/api/state", headers=headers)
        if status != 200:
            fail("the studio stopped answering after a malformed edit")
        print(f"ok: fitted gamma {fitted_gamma:.4g} dragged and raised to {gamma:.4g}; exported "
              f"{', '.join(sorted(os.listdir(exports)))}; screenshot {screenshot}")
    finally:
        driver.quit()
        # Ctrl-C stops it cleanly.
        process.send_signal(signal.SIGINT)
        try:
            out, _ = process.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            process.kill()
            fail("Ctrl-C did not stop the studio")
    if process.returncode != 0 or "studio stopped" not in out:
        fail(f"the studio ended with {process.returncode}: {out}")


if __name__ == "__main__":
    main()
