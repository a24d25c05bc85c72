#!/usr/bin/env python3
"""Drives headless Chromium over the campaign page (see campaign_page.sh) and checks it.

Exit 0 when every check holds; 1 with a one-line reason otherwise."""
import argparse
import contextlib
import os
import sys
import tempfile
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def wait(driver, what, condition, deadline):
    """Polls condition(driver) until it is truthy or the deadline (time.monotonic()) passes."""
    while True:
        try:
            value = condition(driver)
            if value:
                return value
        except Exception:  # the page is between two renders
            value = None
        if time.monotonic() >= deadline:
            fail(f"timed out waiting for {what}")
        time.sleep(0.25)


def browser(user_data_dir):
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ("--headless=new", "--disable-gpu", "--window-size=1400,1000",
                 f"--user-data-dir={user_data_dir}", "--no-first-run", "--disable-extensions"):
        options.add_argument(flag)
    if os.geteuid() == 0:
        options.add_argument("--no-sandbox")  # Chromium's sandbox refuses to run as root
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)


@contextlib.contextmanager
def browser_session():
    """A headless Chromium on a profile of its own, quit (and the profile removed) on the way out."""
    with tempfile.TemporaryDirectory(prefix="rlpos-chromium-") as profile:
        driver = browser(profile)
        try:
            yield driver
        finally:
            driver.quit()


def attribute_int(driver, selector, name):
    return int(driver.find_element(By.CSS_SELECTOR, selector).get_attribute(name))


def full_page_screenshot(driver, file):
    height = driver.execute_script("return document.documentElement.scrollHeight")
    driver.set_window_size(1400, min(max(height, 1000), 12000))
    driver.save_screenshot(file)


def check_plots(driver, positioners, scenarios):
    plots = driver.find_elements(By.CSS_SELECTOR, "#distribution-plots svg.plot")
    if len(plots) != scenarios:
        fail(f"{len(plots)} distribution plots, expected {scenarios}")
    for plot in plots:
        series = plot.find_elements(By.CSS_SELECTOR, "path.series")
        if len(series) != positioners:
            fail(f"plot of {plot.get_attribute('data-scenario')}: {len(series)} series, "
                 f"expected {positioners}")
    maps = driver.find_elements(By.CSS_SELECTOR, "#maps svg.map")
    if len(maps) != scenarios:
        fail(f"{len(maps)} maps, expected {scenarios}")
    for m in maps:
        placements = m.find_elements(By.CSS_SELECTOR, "g.placement")
        if len(placements) != positioners or not m.find_elements(By.CSS_SELECTOR, "rect.building"):
            fail(f"map of {m.get_attribute('data-scenario')}: {len(placements)} placements")
    rows = driver.find_elements(By.CSS_SELECTOR, "#summary-table tbody tr")
    if len(rows) != positioners * scenarios:
        fail(f"summary: {len(rows)} rows, expected {positioners * scenarios}")
    # Each placement against the oracle: a row per positioner (one-UAV scenarios), with its
    # seconds, and a CDF curve per positioner but the oracle.
    rows = driver.find_elements(By.CSS_SELECTOR, "#optimality-table tbody tr")
    if len(rows) != positioners:
        fail(f"optimality: {len(rows)} rows, expected {positioners}")
    curves = driver.find_elements(By.CSS_SELECTOR, '#optimality-plot svg[data-plot="optimality"] path.series')
    if len(curves) != positioners - 1:
        fail(f"optimality CDF: {len(curves)} curves, expected {positioners - 1}")


def check_legends_fit(driver):
    """Every legend entry of every line plot lies inside its plot (none cut at the edge)."""
    cut = driver.execute_script("""
        const cut = [];
        for (const plot of document.querySelectorAll('svg.plot')) {
          const edge = plot.getBoundingClientRect().right;
          for (const t of plot.querySelectorAll('g.legend-item text'))
            if (t.getBoundingClientRect().right > edge + 0.5) cut.push(t.textContent);
        }
        return cut;""")
    if cut:
        fail(f"legend entries cut at the plot's edge: {cut[:3]}")


def check_legend_toggle(driver):
    plot = driver.find_element(By.CSS_SELECTOR, "#distribution-plots svg.plot")
    item = plot.find_element(By.CSS_SELECTOR, "g.legend-item")
    name = item.get_attribute("data-positioner")
    item.click()
    path = plot.find_element(By.CSS_SELECTOR, f'path.series[data-positioner="{name}"]')
    if path.get_attribute("visibility") != "hidden":
        fail(f"a click on the legend entry {name} did not hide its curve")
    plot.find_element(By.CSS_SELECTOR, "g.legend-item").click()
    if path.get_attribute("visibility") != "visible":
        fail(f"a second click on {name} did not show its curve again")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--url", required=True)
    parser.add_argument("--campaign", required=True)
    parser.add_argument("--positioners", type=int, required=True)
    parser.add_argument("--scenarios", type=int, required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--deadline", type=float, default=600)
    args = parser.parse_args()
    deadline = time.monotonic() + args.deadline
    with browser_session() as driver:
        driver.get(args.url)
        row = f'tr.campaign[data-id="{args.campaign}"]'
        wait(driver, "the campaign in the list", lambda d: d.find_elements(By.CSS_SELECTOR, row), deadline)
        first = attribute_int(driver, row + " .progress-text", "data-done")
        total = attribute_int(driver, row + " .progress-text", "data-total")
        if first >= total:
            fail(f"the campaign was over ({first}/{total}) before the page loaded")
        driver.save_screenshot(os.path.join(args.out, "campaign_list.png"))
        # Set once; a reload would lose it.
        driver.execute_script("window.rlposLoadedOnce = true")
        driver.find_element(By.CSS_SELECTOR, row).click()
        done = "#campaign-done"
        wait(driver, "progress to advance", lambda d: attribute_int(d, done, "data-done") > first, deadline)
        wait(driver, "the campaign to finish on the page",
             lambda d: attribute_int(d, done, "data-done") == total, deadline)
        wait(driver, "the plots of the finished campaign",
             lambda d: d.find_element(By.TAG_NAME, "body").get_attribute("data-plotted-done") == str(total),
             deadline)
        if not driver.execute_script("return window.rlposLoadedOnce === true"):
            fail("the page was reloaded")
        check_plots(driver, args.positioners, args.scenarios)
        check_legends_fit(driver)
        check_legend_toggle(driver)
        full_page_screenshot(driver, os.path.join(args.out, "campaign_page.png"))
        print(f"page ok: {first}/{total} at first sight, then {total}/{total} without reload; "
              f"screenshots in {args.out}")


if __name__ == "__main__":
    main()
