//! Command-line interface: the only code that prints. Exit codes: 0 success, 1 the scene has
//! errors, 2 usage errors (clap), 3 files could not be read or written.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "gearloss", version, about = "Gear mesh friction, efficiency and dynamics from a .gear scene")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate a scene and write its report folder (report.md, report.json, SVG plots).
    Run {
        scene: PathBuf,
        /// Folder that receives `<scene-slug>/`.
        #[arg(long, default_value = "reports")]
        out: PathBuf,
    },
    /// Parse and validate a scene only.
    Check { scene: PathBuf },
    /// List the unit table.
    Units,
}

const EXIT_SCENE: u8 = 1;
const EXIT_IO: u8 = 3;

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Run { scene, out } => run(&scene, &out),
        Command::Check { scene } => check(&scene),
        Command::Units => {
            print!("{}", units_table());
            ExitCode::SUCCESS
        }
    }
}

fn read(path: &Path) -> Result<String, ExitCode> {
    std::fs::read_to_string(path).map_err(|e| {
        eprintln!("error: cannot read {}: {e}", path.display());
        ExitCode::from(EXIT_IO)
    })
}

fn report_errors(errors: &gearloss::SceneErrors) -> ExitCode {
    eprint!("{}", errors.render(std::io::stderr().is_terminal()));
    ExitCode::from(EXIT_SCENE)
}

fn check(path: &Path) -> ExitCode {
    let source = match read(path) {
        Ok(s) => s,
        Err(code) => return code,
    };
    match gearloss::check(&path.display().to_string(), &source) {
        Ok(scene) => {
            let n = scene.operating.count();
            println!(
                "{}: scene \"{}\" is valid ({} operating point{})",
                path.display(),
                scene.title,
                n,
                if n == 1 { "" } else { "s" }
            );
            ExitCode::SUCCESS
        }
        Err(e) => report_errors(&e),
    }
}

fn run(path: &Path, out: &Path) -> ExitCode {
    let source = match read(path) {
        Ok(s) => s,
        Err(code) => return code,
    };
    let name = path.display().to_string();
    let scene = match gearloss::check(&name, &source) {
        Ok(s) => s,
        Err(e) => return report_errors(&e),
    };
    let n = scene.operating.count();
    let bar = (std::io::stderr().is_terminal() && n >= 50).then(|| {
        let bar = indicatif::ProgressBar::new(n as u64);
        bar.set_message("operating points");
        bar
    });
    let evaluation = match &bar {
        Some(bar) => gearloss::evaluate_with_progress(&scene, &|| bar.inc(1)),
        None => gearloss::evaluate(&scene),
    };
    if let Some(bar) = &bar {
        bar.finish_and_clear();
    }
    let report = gearloss::report(&scene, &evaluation);
    let rendered = match gearloss::render(&report) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(EXIT_IO);
        }
    };
    match gearloss::write_report_folder(&rendered, out) {
        Ok(dir) => {
            println!("wrote {}", dir.display());
            for (file, _) in &rendered.files {
                println!("  {file}");
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: cannot write the report under {}: {e}", out.display());
            ExitCode::from(EXIT_IO)
        }
    }
}

fn units_table() -> String {
    let mut out = format!("{:<6} {:<24} {:>24} {:<16} {}\n", "unit", "quantity", "in SI", "SI unit", "equals");
    for u in gearloss::scene::units::UNITS {
        let equals = match u.composition {
            Some((1.0, expr)) => expr.to_string(),
            Some((k, expr)) => format!("{k} {expr}"),
            None => String::new(),
        };
        let si = if u.offset != 0.0 { format!("x + {}", u.offset) } else { format!("{:e}", u.factor) };
        out.push_str(&format!(
            "{:<6} {:<24} {:>24} {:<16} {}\n",
            u.name,
            u.dimension.name(),
            si,
            u.dimension.si_unit(),
            equals
        ));
    }
    out.push_str("\nCompound units multiply and divide these: N*m, lbf*in, kg*m^2, lbf*s^2*in, 1/Pa, mm^2/s, N/um.\n");
    out
}
