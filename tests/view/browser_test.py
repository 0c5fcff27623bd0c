#!/usr/bin/env python3
"""The replay viewer in a real browser (docs/viewer.md, "The browser test").

Records a scripted run (tests/view/push_fall.yaml: a NAO pushed over),
serves it with `simswift view --no-browser`, and drives Debian's chromium
(headless) through Debian's python3-selenium and chromium-driver: from the
start it clicks "next event" until the cursor is on the fall, then checks
what the page shows against the recording, read here by a reader of this
file's own (not the server's): the drawn pose of every frame (the robot's
links, the ball) against /tf at that time, the timeline's time, the
selected robot's plot values against /robot0/joints and /robot0/sensors;
one tick on with the step button; ?t=&robot= opening the page at a time;
play and pause; and no error in the console or the page. Keeps a screenshot (--out).

Exit 0 pass, 1 fail, 77 skipped (no chromium, chromedriver or selenium:
scripts/install-deps.sh installs them; CI has them).
"""
import argparse
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time

SKIP = 77
POSE_TOL = 1e-9      # m and quaternion units: the page draws the recorded numbers as they are
VALUE_TOL = 1e-12    # rad, FSR units: plot values are the recorded numbers
SETTLE_S = 60        # s of wall clock the page may take to load and draw (a loaded CI machine)


def skip(why):
    print('browser_test: SKIPPED: ' + why)
    sys.exit(SKIP)


def read_mcap(path):
    """{topic: [(log_time_ns, payload dict)]} and {name: {key: value}} of an MCAP
    file (https://mcap.dev/spec) with uncompressed chunks; a second reader,
    so the page is checked against the file, not against the server."""
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89MCAP0\r\n' and data[-8:] == data[:8], path + ': not a whole MCAP file'
    channels, messages, metadata = {}, {}, {}

    def string(buf, i):
        n, = struct.unpack_from('<I', buf, i)
        return buf[i + 4:i + 4 + n].decode(), i + 4 + n

    def records(buf, i, end):
        while i < end:
            op, length = struct.unpack_from('<BQ', buf, i)
            yield op, buf[i + 9:i + 9 + length]
            i += 9 + length

    def take(op, body):
        if op == 0x04:
            cid, _ = struct.unpack_from('<HH', body, 0)
            topic, _ = string(body, 4)
            channels[cid] = topic
        elif op == 0x05:
            cid, _, t, _ = struct.unpack_from('<HIQQ', body, 0)
            messages.setdefault(channels[cid], []).append((t, json.loads(body[22:])))
        elif op == 0x0C:
            name, i = string(body, 0)
            n, = struct.unpack_from('<I', body, i)
            kv, j, end = {}, i + 4, i + 4 + n
            while j < end:
                k, j = string(body, j)
                kv[k], j = string(body, j)
            metadata[name] = kv

    for op, body in records(data, 8, len(data) - 8):
        if op == 0x0F:
            break  # the summary repeats what the data section has
        if op == 0x06:
            compression, i = string(body, 28)
            assert compression == '', 'compressed chunk'
            n, = struct.unpack_from('<Q', body, i)
            for inner in records(body, i + 8, i + 8 + n):
                take(*inner)
        else:
            take(op, body)
    for v in messages.values():
        v.sort(key=lambda m: m[0])
    return messages, metadata


def at_or_before(msgs, t):
    best = msgs[0]
    for m in msgs:
        if m[0] > t:
            break
        best = m
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--simswift', required=True)
    ap.add_argument('--scenario', help='run it with --record (the test\'s scripted run)')
    ap.add_argument('--recording', help='an existing recording instead of --scenario')
    ap.add_argument('--out', required=True, help='folder for the recording and the screenshot')
    a = ap.parse_args()

    chromium = shutil.which('chromium') or '/usr/bin/chromium'
    driver_path = shutil.which('chromedriver') or '/usr/bin/chromedriver'
    if not os.access(chromium, os.X_OK):
        skip('no chromium (Debian: apt-get install chromium; scripts/install-deps.sh)')
    if not os.access(driver_path, os.X_OK):
        skip('no chromedriver (Debian: apt-get install chromium-driver)')
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.options import Options
        from selenium.webdriver.chrome.service import Service
        from selenium.webdriver.common.by import By
    except ImportError:
        skip('no selenium for ' + sys.executable + ' (Debian: apt-get install python3-selenium)')

    os.makedirs(a.out, exist_ok=True)
    recording = a.recording
    if not recording:
        recording = os.path.join(a.out, 'push_fall.mcap')
        subprocess.run([a.simswift, 'run', a.scenario, '--record', recording], check=True, stdout=subprocess.DEVNULL)
    msgs, meta = read_mcap(recording)
    falls = [m for m in msgs.get('/events', []) if m[1].get('name') == 'fall']
    assert falls, 'the scripted run has no fall event: ' + repr(msgs.get('/events'))
    t_fall = falls[0][0]
    tick = int(meta['simswift']['tick_ns'])

    server = subprocess.Popen([a.simswift, 'view', recording, '--no-browser'], stdout=subprocess.PIPE, text=True)
    profile = tempfile.mkdtemp(prefix='simswift-view-chromium-')
    driver = None
    failures = []

    t_start = time.time()

    def log(what):
        if os.environ.get('BROWSER_TEST_VERBOSE'):
            print('browser_test: %6.2f s %s' % (time.time() - t_start, what))

    def check(ok, what):
        if not ok:
            failures.append(what)
            print('browser_test: FAIL: ' + what)

    try:
        line = server.stdout.readline()
        m = re.search(r'http://127\.0\.0\.1:\d+/', line)
        assert m, 'simswift view printed no address: ' + repr(line)
        url = m.group(0)

        o = Options()
        o.binary_location = chromium
        for arg in ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
                    '--disable-component-update', '--disable-sync', '--no-first-run', '--user-data-dir=' + profile,
                    '--window-size=1280,800', '--enable-unsafe-swiftshader']:  # WebGL on the CPU, no GPU
            o.add_argument(arg)
        o.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
        log('server up')
        driver = webdriver.Chrome(service=Service(driver_path), options=o)
        log('browser up')

        def settled():
            deadline = time.time() + SETTLE_S
            while time.time() < deadline:
                if driver.execute_script('return !!(window.simswiftView && window.simswiftView.settled())'):
                    return driver.execute_script('return window.simswiftView.state()')
                time.sleep(0.05)
            raise AssertionError('the page did not settle in %d s: %r' % (SETTLE_S, driver.execute_script(
                'return window.simswiftView && window.simswiftView.state().errors')))

        driver.get(url + '?robot=0')
        s = settled()
        log('page loaded')
        check(s['t_ns'] == 0, 'the page opens at t = 0 (got %r)' % s['t_ns'])
        # Seek to the fall with the page's own button.
        for _ in range(len(msgs['/events']) + 1):
            if s['t_ns'] >= t_fall:
                break
            driver.find_element(By.ID, 'next-event').click()
            s = settled()
        check(s['t_ns'] == t_fall, 'next event lands on the fall at %d ns (got %r)' % (t_fall, s['t_ns']))
        check(s['time_text'].startswith('t = %.3f s' % (t_fall / 1e9)), 'the timeline shows %.3f s: %r' %
              (t_fall / 1e9, s['time_text']))

        def check_pose(s, t):
            tf_t, tf = at_or_before(msgs['/tf'], t)
            check(s['tf_t_ns'] == tf_t, '/tf drawn from %d ns (got %r)' % (tf_t, s['tf_t_ns']))
            for tr in tf['transforms']:
                d = s['frames'].get(tr['child_frame_id'])
                if d is None:
                    check(False, 'frame %s not drawn' % tr['child_frame_id'])
                    continue
                p, q = tr['translation'], tr['rotation']
                err = max(abs(d['x'] - p['x']), abs(d['y'] - p['y']), abs(d['z'] - p['z']))
                qerr = min(max(abs(d['q' + k] - sign * q[k]) for k in 'xyzw') for sign in (1, -1))
                check(err <= POSE_TOL and qerr <= POSE_TOL, '%s drawn at the recorded pose (off by %g m, %g)' %
                      (tr['child_frame_id'], err, qerr))
            return len(tf['transforms'])

        n = check_pose(s, t_fall)
        check(n > 2 and any(k.startswith('robot0/') for k in s['frames']), 'the robot\'s links are drawn')
        # The selected robot's plots at the cursor.
        jt, j = at_or_before(msgs['/robot0/joints'], t_fall)
        pj = s['plots'].get('joint') or {}
        i = j['name'].index(pj.get('name')) if pj.get('name') in j['name'] else None
        check(i is not None and pj['t_ns'] == jt and abs(pj['position'] - j['position'][i]) <= VALUE_TOL and
              abs(pj['command'] - j['command'][i]) <= VALUE_TOL, 'joint plot at the cursor: %r' % pj)
        st, sen = at_or_before(msgs['/robot0/sensors'], t_fall)
        ps = s['plots'].get('sensors') or {}
        check(ps.get('t_ns') == st and abs(ps['fsr_left'] - sum(sen['fsr_left'])) <= 1e-9 and
              abs(ps['gyroscope']['x'] - sen['gyroscope']['x']) <= VALUE_TOL, 'sensor plots at the cursor: %r' % ps)
        log('fall checked')
        driver.save_screenshot(os.path.join(a.out, 'viewer.png'))
        log('screenshot')

        # One tick on.
        driver.find_element(By.ID, 'step').click()
        s = settled()
        check(s['t_ns'] == t_fall + tick, 'step moves one tick (%d ns) on: %r' % (tick, s['t_ns']))
        check_pose(s, t_fall + tick)

        # Opened at a time by its address (a failing test's report line).
        t_open = 0.5
        driver.get(url + '?t=%g&robot=0' % t_open)
        s = settled()
        check(abs(s['t_s'] - t_open) < 1e-9, '?t=%g opens the page there: %r' % (t_open, s['t_s']))
        check_pose(s, s['t_ns'])

        # Play at 0.1x (a slow machine must not reach the end between the clicks), then pause.
        from selenium.webdriver.support.ui import Select
        Select(driver.find_element(By.ID, 'speed')).select_by_visible_text('0.1')
        driver.find_element(By.ID, 'play').click()
        deadline = time.time() + SETTLE_S
        while driver.execute_script('return window.simswiftView.state().t_s') <= t_open and time.time() < deadline:
            time.sleep(0.05)
        driver.find_element(By.ID, 'play').click()
        s = settled()
        time.sleep(0.3)
        later = settled()
        check(not s['playing'] and s['speed'] == 0.1 and s['t_s'] > t_open and later['t_ns'] == s['t_ns'],
              'play moves the cursor on and pause stops it: t %r s then %r s, playing %r' %
              (s['t_s'], later['t_s'], s['playing']))
        check_pose(s, s['t_ns'])

        errors = [e for e in driver.get_log('browser') if e['level'] == 'SEVERE']
        check(not errors, 'no console errors: %r' % errors)
        check(not s['errors'], 'no page errors: %r' % s['errors'])
    finally:
        if driver:
            driver.quit()
        server.terminate()
        server.wait(timeout=10)
        shutil.rmtree(profile, ignore_errors=True)
    if failures:
        print('browser_test: %d check(s) failed' % len(failures))
        return 1
    print('browser_test: passed (fall at %.3f s; screenshot %s)' % (t_fall / 1e9, os.path.join(a.out, 'viewer.png')))
    return 0


if __name__ == '__main__':
    sys.exit(main())
