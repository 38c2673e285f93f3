# The first output the Python module wrote (gt.write_surface) installed geartrib's SIGINT/SIGTERM/SIGHUP/
# SIGQUIT handler in the interpreter for good: from then on Ctrl-C (or a Jupyter "interrupt kernel") killed
# the interpreter (exit 130) instead of raising KeyboardInterrupt. Promised: a library call leaves the
# host's signal handlers as it found them. (GEARTRIB_PYTHON: the built module's folder.)
import os, signal, sys, tempfile, time
sys.path.insert(0, os.environ.get('GEARTRIB_PYTHON', 'build/python'))
import numpy as np, geartrib as gt
def interrupt(label):
    try:
        os.kill(os.getpid(), signal.SIGINT); time.sleep(0.2); print(label, 'no KeyboardInterrupt')
    except KeyboardInterrupt:
        print(label, 'KeyboardInterrupt (as expected)')
interrupt('before write_surface:')
folder = tempfile.mkdtemp()
gt.write_surface(folder + '/probe.x3p', np.random.default_rng(0).normal(0, 3e-7, (16, 16)), 5e-7)
interrupt('after write_surface:')
print('still alive; left:', sorted(os.listdir(folder)))
