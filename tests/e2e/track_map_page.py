#!/usr/bin/env python3
"""Drives headless Chromium over a scenario map that plays a track run (see track_map_page.sh).

Exit 0 when every check holds; 1 with a one-line reason otherwise."""
import argparse
import os
import sys
import time

from selenium.webdriver.common.by import By

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from campaign_page import browser_session, fail, full_page_screenshot, wait  # noqa: E402


def frame(driver, scenario):
    """What the map shows now: the time label, each UAV marker's shape by positioner, the UEs."""
    return driver.execute_script("""
        const scenario = arguments[0];
        const controls = document.querySelector(`.track-controls[data-scenario="${scenario}"]`);
        const map = document.querySelector(`svg.map[data-scenario="${scenario}"]`);
        const uavs = {};
        for (const g of map.querySelectorAll('g.track-uavs'))
          uavs[g.dataset.positioner] = [...g.querySelectorAll('path.track-uav')].map(p => p.getAttribute('d'));
        return {
          label: controls.querySelector('.track-time').textContent,
          max: Number(controls.querySelector('input.track-slider').max),
          uavs,
          ues: [...map.querySelectorAll('circle.track-ue')].map(c => [c.getAttribute('cx'), c.getAttribute('cy')]),
        };""", scenario)


def slide_to(driver, scenario, index):
    """Sets the slider as a user's drag would: its value, then an input event."""
    driver.execute_script("""
        const slider = document.querySelector(`.track-controls[data-scenario="${arguments[0]}"] input.track-slider`);
        slider.value = arguments[1];
        slider.dispatchEvent(new Event('input', { bubbles: true }));""", scenario, index)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--url", required=True)
    parser.add_argument("--campaign", required=True)
    parser.add_argument("--scenario", required=True)
    parser.add_argument("--positioners", required=True, help="comma-separated, in report order")
    parser.add_argument("--frames", type=int, required=True, help="intervals of the run")
    parser.add_argument("--out", required=True)
    parser.add_argument("--deadline", type=float, default=60)
    args = parser.parse_args()
    deadline = time.monotonic() + args.deadline
    positioners = args.positioners.split(",")
    with browser_session() as driver:
        driver.get(f"{args.url}#/campaign/{args.campaign}")
        controls = f'.track-controls[data-scenario="{args.scenario}"]'
        wait(driver, "the map's time slider", lambda d: d.find_elements(By.CSS_SELECTOR, controls), deadline)
        first = frame(driver, args.scenario)
        if first["max"] != args.frames - 1:
            fail(f"the slider has {first['max'] + 1} frames, expected {args.frames}")
        if sorted(first["uavs"]) != sorted(positioners):
            fail(f"UAV markers of {sorted(first['uavs'])}, expected {sorted(positioners)}")
        if not first["ues"]:
            fail("no UE on the played map")
        slide_to(driver, args.scenario, first["max"])
        last = frame(driver, args.scenario)
        if last["label"] == first["label"]:
            fail(f"the time label stayed {first['label']!r} when the slider moved")
        if not any(last["uavs"][p] != first["uavs"][p] for p in positioners):
            fail("no UAV marker moved with the slider")
        if not any(a != b for a, b in zip(first["ues"], last["ues"])):
            fail("no UE marker moved with the slider")
        card = driver.find_element(By.CSS_SELECTOR, controls).find_element(By.XPATH, "..")
        driver.execute_script("arguments[0].scrollIntoView()", card)
        card.screenshot(os.path.join(args.out, "track_map.png"))
        # Play from the start: the frames advance by themselves.
        slide_to(driver, args.scenario, 0)
        start = frame(driver, args.scenario)["label"]
        driver.find_element(By.CSS_SELECTOR, controls + " .track-play").click()
        wait(driver, "play to advance the time", lambda d: frame(d, args.scenario)["label"] != start, deadline)
        full_page_screenshot(driver, os.path.join(args.out, "track_page.png"))
        print(f"map ok: {first['label']} -> {last['label']}, {len(last['ues'])} UEs, "
              f"UAVs of {', '.join(positioners)}; screenshots in {args.out}")


if __name__ == "__main__":
    main()
