//! The budget's cost model against the committed measurements, its counts against the
//! firmware's, and its refusals.

use super::fit::{fit, parse_measured, parse_scenes, samples};
use super::report::{check_table, worst_error, BAR};
use super::*;
use crate::cmd::root;

fn bench() -> Vec<Counts> {
    scenes().unwrap()
}

fn measured() -> std::collections::HashMap<(String, String), fit::Measured> {
    parse_measured(&fs::read_to_string(root().join("docs").join("mcu.md")).unwrap())
}

/// The bar of the budget: the cost model predicts every benchmark frame (cube, floor,
/// sphere, teapot, fox, cesium_man, in bands and whole) within 15 % of `cargo xtask mcu`'s
/// count, on each instruction set.
#[test]
fn predicts_every_benchmark_frame_within_15_percent() {
    let bench = bench();
    let m = measured();
    for target in ["Cortex-M4F", "Cortex-M0+", "RV32IMC"] {
        let s = samples(&bench, &m, target);
        assert_eq!(
            s.len(),
            12,
            "{target}: a benchmark frame is not in docs/mcu.md"
        );
        let costs = fit(&s, target).unwrap();
        println!("{target}\n{}", check_table(&costs, &s));
        let worst = worst_error(&costs, &s);
        assert!(worst <= BAR, "{target}: {:.1} %", 100.0 * worst);
        assert!(costs.values.iter().all(|v| *v >= 0.0), "{costs:?}");
    }
}

/// The budget's host render counts the Fox as the firmware's code does (the committed
/// row of `host-tests/tests/budget_counts.rs`), from the glTF file baked as the firmware's
/// data was (`--scale 0.02 --center --texture-size 128`) and the Fox scene's view.
#[test]
fn counts_the_fox_as_the_firmware_draws_it() {
    let path = root().join("assets").join("gltf").join("Fox.glb");
    let opts = GltfOpts {
        name: "FOX".into(),
        scale: 0.02,
        center: true,
        texture_size: Some(128),
        levels: None,
        max_texture_kib: 256,
        krate: "fixel".into(),
        rgb565: crate::bake::DEFAULT_RGB565.into(),
        order_by_height: false,
    };
    let model = model_from(&path, bake_gltf::load(&path).unwrap(), &opts).unwrap();
    let (c, loads) = render::count(&model, (240, 320), &render::view()).unwrap();
    let fox = bench().into_iter().find(|c| c.scene == "fox").unwrap();
    assert_eq!(
        (c.vertices, c.triangles, c.binned, c.pieces, c.pixels),
        (
            fox.vertices,
            fox.triangles,
            fox.binned,
            fox.pieces,
            fox.pixels
        )
    );
    assert_eq!(loads.len(), 40);
    assert_eq!(loads.iter().map(|l| l.pieces).sum::<u64>(), fox.pieces);
}

/// The Fox through the whole command: a report with memory, frame times and the check.
#[test]
fn budgets_a_gltf_model() {
    let args = BudgetArgs {
        model: root().join("assets/gltf/Fox.glb").display().to_string(),
        chip: parse_chip("esp32c3").unwrap(),
        size: None,
        coverage: None,
    };
    let t = run(&args).unwrap();
    for want in [
        "flash, total",
        "RAM, total",
        "serial, 1 core",
        "largest error",
        "Assumptions",
    ] {
        assert!(t.contains(want), "{want}:\n{t}");
    }
}

#[test]
fn refuses_unknown_chips_sizes_coverages_and_models() {
    let e = parse_chip("esp32s3").unwrap_err();
    assert!(e.contains("rp2040, rp2350, stm32f4, esp32c3"), "{e}");
    assert_eq!(parse_chip("RP2040").unwrap().name, "RP2040");
    assert_eq!(parse_chip("esp32-c3").unwrap().name, "ESP32-C3");
    assert_eq!(parse_size("240x320"), Ok((240, 320)));
    for bad in ["240", "0x320", "240x", "x", "240x99999", "a x b"] {
        assert!(parse_size(bad).is_err(), "{bad}");
    }
    for bad in ["0", "-0.1", "1.5", "nan", "half"] {
        assert!(parse_coverage(bad).is_err(), "{bad}");
    }
    let args = |model: &str| BudgetArgs {
        model: model.into(),
        chip: parse_chip("rp2040").unwrap(),
        size: None,
        coverage: None,
    };
    let e = run(&args("model.obj")).unwrap_err();
    assert!(
        e.contains("neither a .glb/.gltf file nor a benchmark scene"),
        "{e}"
    );
    let e = run(&args("/nonexistent/model.glb")).unwrap_err();
    assert!(e.contains("/nonexistent/model.glb"), "{e}");
    let mut a = args("cube");
    a.size = Some((240, 320));
    let e = run(&a).unwrap_err();
    assert!(e.contains("measured at 320 x 240"), "{e}");
}

#[test]
fn a_benchmark_scene_shows_its_measured_count() {
    let t = run(&BudgetArgs {
        model: "teapot".into(),
        chip: parse_chip("stm32f4").unwrap(),
        size: None,
        coverage: None,
    })
    .unwrap();
    assert!(t.contains("measured (`cargo xtask mcu`)"), "{t}");
}

#[test]
fn scenes_csv_lines_that_are_not_counts_are_refused() {
    assert!(parse_scenes("cube,bins,320,240\n").is_err());
    assert!(parse_scenes("cube,strips,320,240,8,24,12,6,96,35485\n").is_err());
}
