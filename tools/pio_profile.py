# pio_profile.py - PlatformIO's pre-build step (platformio.ini extra_scripts):
# the firmware's robot profile, build/gen/ROBOT/robot_profile.h, written from
# robots/ROBOT.ini's [firmware] section by `make` (tools/mkprofile.c; the host's
# C compiler, make and libinih-dev are needed). ROBOT is the environment's
# custom_robot option (default paper); its build_flags carry -Ibuild/gen/ROBOT.
# On failure the build stops with make's one line (exit 2: a bad robot file,
# 3: make could not run).
import subprocess

Import("env")  # noqa: F821 (PlatformIO's SCons environment)

robot = env.GetProjectOption("custom_robot", "paper")  # noqa: F821
target = "build/gen/%s/robot_profile.h" % robot
try:
    rc = subprocess.run(["make", "-s", "--no-print-directory", target], cwd=env.subst("$PROJECT_DIR")).returncode  # noqa: F821
except OSError as e:
    print("pio_profile: make: %s (the robot profile needs make and a host C compiler)" % e)
    env.Exit(3)  # noqa: F821
if rc != 0:
    print("pio_profile: make %s failed (exit %d)" % (target, rc))
    env.Exit(2)  # noqa: F821
