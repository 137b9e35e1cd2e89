//! An X server of the tests' own (Xvfb; CI installs it: .ci/run), for the viewer's tests in a
//! real window; for two monitors, Xorg with the dummy driver (Xvfb has one CRTC, so one
//! monitor, whatever its screens), its second output placed with xrandr.

use std::path::{Path, PathBuf};
use std::process::{Child, Command};

/// An X server of our own, stopped on drop.
pub struct Xvfb {
    child: Child,
    /// The `DISPLAY` it serves.
    pub display: String,
}

impl Xvfb {
    /// Start one on a free display (Xvfb picks it and says which: `-displayfd`), or `None`
    /// where the machine has no Xvfb.
    pub fn start() -> Option<Self> {
        let child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1024x768x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::null())
            .spawn()
            .ok()?;
        Some(Self::serving(child, "Xvfb"))
    }

    /// The server `child` started with `-displayfd 1`, on the display it says it took.
    fn serving(mut child: Child, what: &str) -> Self {
        use std::io::BufRead;
        let mut line = String::new();
        let stdout = child.stdout.take().expect("piped");
        std::io::BufReader::new(stdout)
            .read_line(&mut line)
            .unwrap();
        let n: u32 = line
            .trim()
            .parse()
            .unwrap_or_else(|_| panic!("{what} did not come up (said {line:?})"));
        Self {
            child,
            display: format!(":{n}"),
        }
    }

    /// Two monitors side by side: 1024×768 at 0,0 and 640×480 at 1024,0 (Xorg's dummy driver
    /// and xrandr), or `None` where the machine lacks them (CI installs them: .ci/run).
    pub fn two_monitors() -> Option<Self> {
        let driver = Path::new("/usr/lib/xorg/modules/drivers/dummy_drv.so");
        let xrandr = Command::new("xrandr").arg("--version").output().is_ok();
        if !driver.exists() || !xrandr {
            return None;
        }
        let dir = super::out_dir().join("xorg_dummy");
        std::fs::create_dir_all(&dir).unwrap();
        let config = dir.join("dummy.conf");
        std::fs::write(
            &config,
            "Section \"Device\"\n Identifier \"dummy\"\n Driver \"dummy\"\n VideoRam 64000\nEndSection\n\
             Section \"Screen\"\n Identifier \"screen\"\n Device \"dummy\"\n DefaultDepth 24\n \
             SubSection \"Display\"\n  Depth 24\n  Virtual 2048 1024\n EndSubSection\nEndSection\n",
        )
        .unwrap();
        let child = Command::new("Xorg")
            .args(["-displayfd", "1", "-noreset", "-nolisten", "tcp", "-config"])
            .arg(&config)
            .arg("-logfile")
            .arg(dir.join(format!("xorg-{}.log", std::process::id())))
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::null())
            .spawn()
            .ok()?;
        let x = Self::serving(child, "Xorg (dummy)");
        let xrandr = |args: &[&str]| {
            let status = Command::new("xrandr")
                .args(args)
                .env("DISPLAY", &x.display)
                .status()
                .unwrap();
            assert!(status.success(), "xrandr {args:?}");
        };
        let mode = [
            "640x480_two",
            "25.175",
            "640",
            "656",
            "752",
            "800",
            "480",
            "490",
            "492",
            "525",
        ];
        xrandr(&[&["--newmode"][..], &mode].concat());
        xrandr(&["--addmode", "DUMMY1", mode[0]]);
        xrandr(&[
            "--output",
            "DUMMY1",
            "--mode",
            mode[0],
            "--right-of",
            "DUMMY0",
        ]);
        Some(x)
    }

    /// Run the CLI on this display; (success, stdout, stderr).
    pub fn cli(&self, args: &[&str]) -> (bool, String, String) {
        let out = Command::new(env!("CARGO_BIN_EXE_autostereo"))
            .args(args)
            .env("DISPLAY", &self.display)
            .env_remove("WAYLAND_DISPLAY")
            .env("RUST_LOG", "off")
            .output()
            .unwrap();
        (
            out.status.success(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    }
}

impl Xvfb {
    /// `view ARGS --screenshot SHOT`, which must succeed: where the presented frame was saved.
    pub fn screenshot(&self, args: &[&str], shot: &Path) -> PathBuf {
        let mut all = vec!["view"];
        all.extend_from_slice(args);
        all.extend(["--screenshot", shot.to_str().unwrap()]);
        let (ok, _, err) = self.cli(&all);
        assert!(ok, "{all:?}: {err}");
        shot.to_path_buf()
    }
}

/// `command ARGS` rendered headless at `--origin ORIGIN` into `path` (which it returns): the
/// image the viewer must present in a window at that position (the mask follows the window).
pub fn headless(command: &str, args: &[&str], origin: &str, path: &Path) -> PathBuf {
    let mut all = vec![command, "--origin", origin, "--out", path.to_str().unwrap()];
    all.extend_from_slice(args);
    let (ok, err) = super::cli(&all);
    assert!(ok, "{all:?}: {err}");
    path.to_path_buf()
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        // SIGTERM, so that Xvfb removes its lock file and socket (a kill would leave them).
        let _ = Command::new("kill")
            .args(["-TERM", &self.child.id().to_string()])
            .status();
        let _ = self.child.wait();
    }
}

/// An Xvfb of our own, or — on a machine without it — the viewer's clear error asserted and
/// `None`.
pub fn xvfb_or_clear_error() -> Option<Xvfb> {
    if let Some(x) = Xvfb::start() {
        return Some(x);
    }
    let (ok, stderr) = cli_without_display(&["view", "--quit-after-frames", "1"]);
    assert!(!ok, "a window opened without a display");
    assert!(stderr.contains("window system"), "{stderr}");
    None
}

/// Run the CLI with no window system to reach (`DISPLAY`, `WAYLAND_DISPLAY` unset): what the
/// viewer refuses before it opens a window. (success, stderr)
pub fn cli_without_display<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_autostereo"))
        .args(args)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
