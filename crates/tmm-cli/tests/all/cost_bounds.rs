//! Small inputs, bounded cost: a task file larger than the cap (an endless
//! device, a pipe that keeps writing) is refused after reading one byte more;
//! a long line is cut in the snippet under a message; a cam table, the
//! function generation's positions and a sweep larger than their caps are
//! refused with a message naming the field or option and the limit.

use std::io::Write;

use crate::common::{self, repo, run};

fn tmp(name: &str) -> std::path::PathBuf {
    common::tmp("cost_bounds", name)
}

#[test]
fn a_task_file_past_the_cap_is_refused_naming_the_file_and_the_limit() {
    let d = tmp("big");
    let f = d.join("big.toml");
    // 4 MiB + 1 of comments: valid TOML, refused for its size alone
    let mut text = String::from("title = \"big\"\n");
    let line = format!("#{}\n", "x".repeat(1023));
    while text.len() <= 4 << 20 {
        text.push_str(&line);
    }
    std::fs::write(&f, &text).unwrap();
    let (code, _, err) = run(&["linkage", f.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("big.toml") && err.contains("4194304"), "{err}");
    assert!(err.len() < 2000, "{} bytes of message", err.len());
}

#[cfg(target_os = "linux")]
#[test]
fn an_endless_device_and_a_fifo_are_refused_after_the_cap() {
    let (code, _, err) = run(&["linkage", "/dev/zero"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("/dev/zero") && err.contains("4194304"), "{err}");
    let d = tmp("fifo");
    let fifo = d.join("task.toml");
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let path = fifo.clone();
    // the writer keeps writing until the reader closes the pipe
    let writer = std::thread::spawn(move || {
        let mut w = std::fs::OpenOptions::new().write(true).open(path).unwrap();
        let block = vec![b'#'; 1 << 16];
        let mut sent = 0usize;
        while w.write_all(&block).is_ok() {
            sent += block.len();
            if sent > 64 << 20 {
                break;
            }
        }
        sent
    });
    let (code, _, err) = run(&["linkage", fifo.to_str().unwrap()]);
    let sent = writer.join().unwrap();
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("4194304"), "{err}");
    assert!(sent < 64 << 20, "the reader read {sent} bytes");
}

#[test]
fn a_long_line_is_cut_in_the_snippet_under_a_message() {
    let d = tmp("long-line");
    let base = std::fs::read_to_string(repo().join("examples/seed-001-fourbar.toml")).unwrap();
    let text = base.replacen("[linkage]\n", &format!("[linkage]\nbogus = \"{}\"\n", "y".repeat(1_000_000)), 1);
    let f = d.join("task.toml");
    std::fs::write(&f, text).unwrap();
    let (code, _, err) = run(&["linkage", f.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("bogus") && err.contains("task.toml:"), "{err}");
    assert!(err.len() < 10_000, "{} bytes of message", err.len());
}

#[test]
fn a_cam_table_past_the_cap_is_refused_and_one_at_the_cap_runs() {
    let d = tmp("cam-table");
    let task = |n: usize| {
        let vals: Vec<String> = (0..n)
            .map(|i| format!("{:.4}", (std::f64::consts::TAU * i as f64 / (n - 1) as f64).sin()))
            .collect();
        format!(
            "title = \"cam table\"\n[cam]\nfollower = \"translating-roller\"\nstroke = \"13 mm\"\nphases = \"rise 108 table({}); dwell 15; return 108 sine; dwell 129\"\nmax_pressure = 30\n",
            vals.join(", ")
        )
    };
    let f = d.join("over.toml");
    std::fs::write(&f, task(10_001)).unwrap();
    let (code, _, err) = run(&["cam", f.to_str().unwrap(), "--json"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("table") && err.contains("10000") && err.contains("over.toml:"),
        "{err}"
    );
    let f = d.join("at.toml");
    std::fs::write(&f, task(10_000)).unwrap();
    let (code, out, err) = run(&["cam", f.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert!(v.is_object());
}

#[test]
fn function_generation_positions_past_the_cap_are_refused_located() {
    let d = tmp("positions");
    let n = 1001;
    let pos: Vec<String> = (0..n)
        .map(|i| {
            let t = i as f64 / (n - 1) as f64;
            format!("[\"{:.6} deg\", \"{:.6} deg\"]", 10.0 + 100.0 * t, 40.0 + 60.0 * t.powf(1.1))
        })
        .collect();
    let f = d.join("task.toml");
    std::fs::write(
        &f,
        format!(
            "title = \"fg\"\n[synthesis]\nkind = \"function-generation\"\npositions = [{}]\nframe = \"300 mm\"\n",
            pos.join(", ")
        ),
    )
    .unwrap();
    let out = d.join("o");
    let (code, _, err) = run(&["run", f.to_str().unwrap(), "--out", out.to_str().unwrap(), "--no-pdf"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("positions") && err.contains("1000") && err.contains("task.toml:4:"),
        "{err}"
    );
    assert!(err.len() < 10_000, "{} bytes of message", err.len());
    assert!(!out.exists());
}

#[test]
fn a_sweep_past_the_cap_is_refused_naming_the_limit() {
    let (code, _, err) = run(&[
        "synth",
        "crank-slider",
        "--stroke",
        "300 mm",
        "--k",
        "1.2",
        "--sweep",
        "lambda=2..6:10001",
        "--json",
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--sweep") && err.contains("10000"), "{err}");
}
