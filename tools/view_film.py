#!/usr/bin/python3
"""Films a stretch of a recording with simswift's own viewer (docs/viewer.md):
serves FILE.mcap with `simswift view --no-browser`, opens the page in
headless chromium (Debian's chromium, chromium-driver, python3-selenium),
steps the page's cursor through [--from, --to] and screenshots each step;
ffmpeg joins them into an MP4 or a GIF (by --out's extension); --out
FILE.png keeps one screenshot, at --from.

  tools/view_film.py build/simswift run.mcap --from 0.5 --to 3 --out docs/images/viewer.gif
  tools/view_film.py build/simswift run.mcap --from 1.45 --out docs/images/viewer.png

--step: run time per frame (s, default 0.05); --fps: frames per second of
the film (default 10: with the default step, half real time); --robot,
--follow robot|ball|none; --size WxH of the browser window.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('simswift')
    ap.add_argument('recording')
    ap.add_argument('--from', dest='start', type=float, default=0.0)
    ap.add_argument('--to', dest='end', type=float, help='required for a film')
    ap.add_argument('--step', type=float, default=0.05)
    ap.add_argument('--fps', type=float, default=10)
    ap.add_argument('--robot', type=int, default=0)
    ap.add_argument('--follow', default='robot', choices=['robot', 'ball', 'none'])
    ap.add_argument('--size', default='1000x620')
    ap.add_argument('--out', required=True, help='FILE.mp4, FILE.gif or FILE.png')
    a = ap.parse_args()
    still = a.out.endswith('.png')
    if still:
        a.end = a.start
    elif a.end is None:
        ap.error('a film needs --to')
    if not (0 <= a.start <= a.end) or (not still and a.start == a.end) or a.step <= 0 or a.fps <= 0:
        ap.error('need 0 <= --from < --to, --step > 0, --fps > 0')
    if not re.fullmatch(r'\d+x\d+', a.size):
        ap.error('--size is WxH')
    if not a.out.endswith(('.mp4', '.gif', '.png')):
        ap.error('--out must end in .mp4, .gif or .png')
    for tool in ('chromium', 'chromedriver', 'ffmpeg'):
        if not shutil.which(tool):
            sys.exit('view_film: %s not found (scripts/install-deps.sh installs it)' % tool)
    from selenium import webdriver
    from selenium.webdriver.chrome.options import Options
    from selenium.webdriver.chrome.service import Service

    server = subprocess.Popen([a.simswift, 'view', a.recording, '--no-browser'], stdout=subprocess.PIPE, text=True)
    work = tempfile.mkdtemp(prefix='simswift-film-')
    driver = None
    try:
        line = server.stdout.readline()
        m = re.search(r'http://127\.0\.0\.1:\d+/', line)
        if not m:
            sys.exit('view_film: simswift view printed no address: %r' % line)
        o = Options()
        o.binary_location = shutil.which('chromium')
        for arg in ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
                    '--disable-component-update', '--disable-sync', '--no-first-run', '--enable-unsafe-swiftshader',
                    '--user-data-dir=' + os.path.join(work, 'profile'), '--window-size=' + a.size.replace('x', ',')]:
            o.add_argument(arg)
        driver = webdriver.Chrome(service=Service(shutil.which('chromedriver')), options=o)
        driver.get('%s?t=%g&robot=%d&follow=%s' % (m.group(0), a.start, a.robot, a.follow))

        def settle():
            deadline = time.time() + 60
            while not driver.execute_script('return !!(window.simswiftView && window.simswiftView.settled())'):
                if time.time() > deadline:
                    sys.exit('view_film: the page did not settle in 60 s')
                time.sleep(0.02)

        settle()
        n = int(round((a.end - a.start) / a.step)) + 1
        for k in range(n):
            driver.execute_script('window.simswiftView.seek(arguments[0])', a.start + k * a.step)
            settle()
            time.sleep(0.05)  # one more animation frame: the drawn canvas, not the one before
            driver.save_screenshot(os.path.join(work, 'frame%05d.png' % k))
        frames = os.path.join(work, 'frame%05d.png')
        if still:
            shutil.copyfile(frames % 0, a.out)
            print('view_film: %.2f s of the run -> %s' % (a.start, a.out))
            return
        if a.out.endswith('.gif'):
            # One palette for the whole film (ffmpeg's palettegen/paletteuse), 720 px wide.
            vf = 'scale=720:-1:flags=lanczos,split[a][b];[a]palettegen=max_colors=128[p];[b][p]paletteuse=dither=bayer'
            cmd = ['ffmpeg', '-y', '-loglevel', 'error', '-framerate', str(a.fps), '-i', frames, '-vf', vf, a.out]
        else:
            cmd = ['ffmpeg', '-y', '-loglevel', 'error', '-framerate', str(a.fps), '-i', frames, '-c:v', 'libx264',
                   '-pix_fmt', 'yuv420p', '-vf', 'scale=trunc(iw/2)*2:trunc(ih/2)*2', a.out]
        subprocess.run(cmd, check=True)
        print('view_film: %d frames, %.2f-%.2f s of the run -> %s' % (n, a.start, a.end, a.out))
    finally:
        if driver:
            driver.quit()
        server.terminate()
        server.wait(timeout=10)
        shutil.rmtree(work, ignore_errors=True)


if __name__ == '__main__':
    main()
