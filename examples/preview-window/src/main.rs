//! fixel's benchmark scenes in an `embedded-graphics-simulator` window: 320 x 240 RGB565,
//! drawn in 8-row bands through `BandRenderer` and flushed to the window's display as a
//! firmware flushes them to an SPI display. Keys turn the camera around the model, switch
//! the scene and the technique, and print the frame's instruction estimate on a chosen chip.
//!
//! ```text
//! cargo xtask preview                  # installs SDL2 if missing, opens the window
//! cargo xtask preview --scene teapot --chip m0plus
//! cargo run --release --manifest-path examples/preview-window/Cargo.toml -- --help
//! ```
//!
//! Keys: arrows orbit (15 degrees a press), `+` / `-` move the camera closer or farther,
//! `t` next technique, `s` next scene, `c` next chip, `e` the estimate again, `r` the
//! scene's start view, `h` this help, `q` or Escape quits.
//!
//! Without a person at the keys: `--frames N` draws N frames (the model turning 15 degrees
//! between frames) and exits; `--out-dir DIR` writes every frame shown as
//! `DIR/frame-NNN.png` (the pixels the window shows, RGB565 widened to 8 bits as the
//! simulator widens them); after each frame, a line `frame N shown: ...` goes to standard
//! output; `--hold` keeps the last frame on screen until standard input closes.
//! `cargo xtask preview --check` runs it under Xvfb, presses keys with xdotool and
//! compares screenshots of the window with these PNGs.

mod estimate;
#[allow(dead_code)] // Shared with the firmwares and the report; the window uses a part.
#[path = "../../firmware/src/modes.rs"]
mod modes;
mod scene;

use std::error::Error as StdError;
use std::fs::{self, File};
use std::io::{self, BufWriter, Read, Write};
use std::path::{Path, PathBuf};

use clap::Parser;
use embedded_graphics::geometry::Size;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use embedded_graphics_simulator::sdl2::Keycode;
use embedded_graphics_simulator::{
    OutputSettingsBuilder, SimulatorDisplay, SimulatorEvent, Window,
};
use fixel::math::{Angle, Fx};

use estimate::{Chip, Estimate};
use scene::{technique_name, Orbit, SceneKind, Scenes, H, ROWS, TECHNIQUES, W};

/// The window's title (what `cargo xtask preview --check` finds it by).
const TITLE: &str = "fixel preview";
/// One orbit step, in degrees.
const STEP_DEG: i32 = 15;

/// fixel's benchmark scenes in a desktop window, drawn in bands as a firmware draws them.
#[derive(Parser, Debug)]
#[command(name = "preview-window")]
struct Args {
    /// Scene: cube, sphere or teapot
    #[arg(long, default_value = "cube")]
    scene: String,
    /// Technique (`lit-bilinear-sub64`, ...; default: the scene's firmware mode); `t` steps
    #[arg(long)]
    technique: Option<String>,
    /// Chip of the instruction estimate: m4f, m0plus or rv32
    #[arg(long, default_value = "m4f")]
    chip: String,
    /// Draw this many frames, the model turning 15 degrees between them, then exit
    #[arg(long)]
    frames: Option<u32>,
    /// Write each frame shown as DIR/frame-NNN.png
    #[arg(long)]
    out_dir: Option<PathBuf>,
    /// With --frames: keep the last frame on screen until standard input closes
    #[arg(long)]
    hold: bool,
}

/// What the window shows.
struct State {
    scene: SceneKind,
    technique: usize,
    chip: Chip,
    orbit: Orbit,
    /// Frames shown so far.
    shown: u32,
    /// Pixels drawn in the last frame.
    pixels: u32,
}

impl State {
    fn estimate(&self) -> Estimate {
        let name = technique_name(&TECHNIQUES[self.technique]);
        Estimate::new(self.scene, &name, self.chip, self.pixels)
    }

    fn print_estimate(&self) {
        println!("  {}: {}", self.chip, self.estimate());
    }
}

fn help() {
    println!(
        "keys: arrows orbit ({STEP_DEG} degrees), + / - closer / farther, t technique, \
         s scene, c chip, e estimate, r start view, h help, q or Escape quits"
    );
    let names: Vec<String> = TECHNIQUES.iter().map(technique_name).collect();
    println!("techniques: {}", names.join(", "));
}

/// An angle of `deg` whole degrees.
fn degrees(deg: i32) -> Angle {
    Angle::from_degrees(Fx::from_num(deg))
}

/// Writes `frame` (`W * H` RGB565, row 0 first) as an 8-bit RGB PNG, each channel widened
/// as embedded-graphics widens it (`Rgb888::from`), which is what the window shows.
fn write_png(path: &Path, frame: &[Rgb565]) -> Result<(), Box<dyn StdError>> {
    let rgb: Vec<u8> = frame
        .iter()
        .flat_map(|&c| {
            let c = Rgb888::from(c);
            [c.r(), c.g(), c.b()]
        })
        .collect();
    let mut png = png::Encoder::new(BufWriter::new(File::create(path)?), W, H);
    png.set_color(png::ColorType::Rgb);
    png.set_depth(png::BitDepth::Eight);
    png.write_header()?.write_image_data(&rgb)?;
    Ok(())
}

/// Draws the state's frame in bands into `display`, shows it, writes its PNG and says so.
fn show(
    state: &mut State,
    scenes: &mut Scenes,
    display: &mut SimulatorDisplay<Rgb565>,
    window: &mut Window,
    frame: &mut [Rgb565],
    out_dir: Option<&Path>,
) -> Result<(), Box<dyn StdError>> {
    let technique = &TECHNIQUES[state.technique];
    let stats = scenes.render(state.scene, technique, &state.orbit, display, frame)?;
    state.pixels = stats.pixels;
    // Twice: the second update is queued behind the first, so the frame is on screen when
    // the line below is printed.
    window.update(display);
    window.update(display);
    if let Some(dir) = out_dir {
        write_png(&dir.join(format!("frame-{:03}.png", state.shown)), frame)?;
    }
    let (yaw, pitch) = state.orbit.degrees();
    println!(
        "frame {} shown: {} {}, yaw {yaw} deg, pitch {pitch} deg, distance {}: {} px in {} \
         bands of {ROWS} rows{}",
        state.shown,
        state.scene.name(),
        technique_name(technique),
        state.orbit.distance,
        stats.pixels,
        stats.bands,
        if stats.reprojected {
            " (re-projected per band)"
        } else {
            ""
        },
    );
    state.print_estimate();
    io::stdout().flush()?;
    state.shown += 1;
    Ok(())
}

/// What a key does.
enum Action {
    Redraw,
    Quit,
    Nothing,
}

fn on_key(state: &mut State, key: Keycode) -> Action {
    let o = &mut state.orbit;
    match key {
        Keycode::LEFT => o.yaw = o.yaw - degrees(STEP_DEG),
        Keycode::RIGHT => o.yaw = o.yaw + degrees(STEP_DEG),
        Keycode::UP => o.pitch = o.pitch - degrees(STEP_DEG),
        Keycode::DOWN => o.pitch = o.pitch + degrees(STEP_DEG),
        Keycode::EQUALS | Keycode::PLUS | Keycode::KP_PLUS => {
            o.distance = (o.distance - Fx::from_num(0.5)).max(Fx::from_num(2));
        }
        Keycode::MINUS | Keycode::KP_MINUS => {
            o.distance = (o.distance + Fx::from_num(0.5)).min(Fx::from_num(15));
        }
        Keycode::T => state.technique = (state.technique + 1) % TECHNIQUES.len(),
        Keycode::S => {
            state.scene = state.scene.next();
            state.orbit = state.scene.start();
        }
        Keycode::R => state.orbit = state.scene.start(),
        Keycode::C => {
            state.chip = state.chip.next();
            state.print_estimate();
            return Action::Nothing;
        }
        Keycode::E => {
            state.print_estimate();
            return Action::Nothing;
        }
        Keycode::H => {
            help();
            return Action::Nothing;
        }
        Keycode::Q | Keycode::ESCAPE => return Action::Quit,
        _ => return Action::Nothing,
    }
    Action::Redraw
}

fn main() -> Result<(), Box<dyn StdError>> {
    let args = Args::parse();
    let scene = SceneKind::parse(&args.scene)
        .ok_or_else(|| format!("unknown scene `{}` (cube, sphere, teapot)", args.scene))?;
    let chip = Chip::parse(&args.chip)
        .ok_or_else(|| format!("unknown chip `{}` (m4f, m0plus, rv32)", args.chip))?;
    let technique = match &args.technique {
        None => scene.firmware_technique(),
        Some(t) => TECHNIQUES
            .iter()
            .position(|m| technique_name(m) == *t)
            .ok_or_else(|| format!("unknown technique `{t}` (h in the window lists them)"))?,
    };
    if let Some(dir) = &args.out_dir {
        fs::create_dir_all(dir)?;
    }

    let mut scenes = Scenes::new()?;
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(W, H));
    // One window pixel per display pixel: the window shows the frame as it is.
    let settings = OutputSettingsBuilder::new()
        .scale(1)
        .pixel_spacing(0)
        .build();
    let mut window = Window::new(TITLE, &settings);
    let mut frame = vec![Rgb565::BLACK; (W * H) as usize];
    let mut state = State {
        scene,
        technique,
        chip,
        orbit: scene.start(),
        shown: 0,
        pixels: 0,
    };
    let out_dir = args.out_dir.as_deref();

    if let Some(frames) = args.frames {
        for i in 0..frames {
            if i > 0 {
                state.orbit.yaw = state.orbit.yaw + degrees(STEP_DEG);
            }
            show(
                &mut state,
                &mut scenes,
                &mut display,
                &mut window,
                &mut frame,
                out_dir,
            )?;
        }
        if args.hold {
            // Until the caller closes standard input (a screenshot is taken meanwhile).
            io::stdin().read_to_end(&mut Vec::new())?;
        }
        return Ok(());
    }

    help();
    show(
        &mut state,
        &mut scenes,
        &mut display,
        &mut window,
        &mut frame,
        out_dir,
    )?;
    loop {
        let events: Vec<SimulatorEvent> = window.events().collect();
        let mut redraw = false;
        for event in events {
            let action = match event {
                SimulatorEvent::Quit => Action::Quit,
                SimulatorEvent::KeyDown { keycode, .. } => on_key(&mut state, keycode),
                _ => Action::Nothing,
            };
            match action {
                Action::Quit => return Ok(()),
                Action::Redraw => redraw = true,
                Action::Nothing => {}
            }
        }
        if redraw {
            show(
                &mut state,
                &mut scenes,
                &mut display,
                &mut window,
                &mut frame,
                out_dir,
            )?;
        } else {
            // Keeps the window drawn and paces the loop (the simulator's 60 fps limit).
            window.update(&display);
        }
    }
}
