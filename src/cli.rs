//! Command-line interface: the only code that prints. Exit codes: 0 success, 1 the scene has
//! errors, 2 usage errors (clap), 3 files could not be read or written.
#![allow(clippy::print_stdout, clippy::print_stderr)]

/// Print a line to stdout or stderr, ignoring a closed pipe (`gearloss check x | head -1` must not
/// panic as `println!` would).
macro_rules! say {
    (out, $($t:tt)*) => {{ use std::io::Write as _; let _ = write!(std::io::stdout().lock(), $($t)*); }};
    (err, $($t:tt)*) => {{ use std::io::Write as _; let _ = write!(std::io::stderr().lock(), $($t)*); }};
}
macro_rules! outln {
    ($($t:tt)*) => {{ use std::io::Write as _; let _ = writeln!(std::io::stdout().lock(), $($t)*); }};
}
macro_rules! errln {
    ($($t:tt)*) => {{ use std::io::Write as _; let _ = writeln!(std::io::stderr().lock(), $($t)*); }};
}

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
    /// Evaluate a scene and write its report folder (report.md, report.json, SVG plots, record files).
    Run {
        scene: PathBuf,
        /// Folder that receives `<scene-slug>/` (or `<scene-slug>.shard-K-of-N/` with --shard).
        #[arg(long, default_value = "reports")]
        out: PathBuf,
        /// Evaluate only the K-th of N equal blocks of the operating points (1 ≤ K ≤ N), writing its
        /// record files and a manifest for `gearloss merge`.
        #[arg(long, value_name = "K/N", value_parser = parse_shard)]
        shard: Option<gearloss::Shard>,
        /// The record files to write: a list of csv, jsonl, parquet (default csv,jsonl; parquet for
        /// big sweeps: typed, compressed, fast to read); a drive's are drive_records.*.
        #[arg(long, value_name = "FORMATS", default_value = "csv,jsonl")]
        records: gearloss::RecordFormats,
    },
    /// Combine the shard folders of one scene into the report a single run gives.
    Merge {
        #[arg(required = true)]
        shards: Vec<PathBuf>,
        /// Folder that receives `<scene-slug>/`.
        #[arg(long, default_value = "reports")]
        out: PathBuf,
    },
    /// Draw report.md and every plot of a report folder again from its report.json alone.
    Render { folder: PathBuf },
    /// Read a REXS gear-unit model (.rexs, .rexsj, .rexsz) and write a commented scene from it.
    Import {
        model: PathBuf,
        /// The scene to write (it must not exist yet); default: the model's name with `.gear`.
        #[arg(short, long)]
        out: Option<PathBuf>,
    },
    /// Parse and validate a scene, and say what `run` would compute.
    Check {
        scene: PathBuf,
        /// Print the lowered form instead (`lowered`: the checked scene as JSON, every quantity in SI).
        #[arg(long, value_parser = ["lowered"])]
        emit: Option<String>,
    },
    /// List the unit table.
    Units,
    /// List the friction laws with their arguments, needs and sources.
    Laws,
    /// List the oil catalogue (ISO VG grades, base oils and their data).
    Oils,
    /// List the bearing types, their loss factors, and the keys of bearings and seals.
    Bearings,
    /// Write a commented template scene to start from.
    New {
        /// The file to write (it must not exist yet).
        #[arg(default_value = "scene.gear")]
        scene: PathBuf,
        /// The template to write.
        #[arg(long, default_value = "pair", value_parser = template_kinds())]
        kind: String,
    },
}

const EXIT_SCENE: u8 = 1;
const EXIT_IO: u8 = 3;

/// `K/N` with 1 ≤ K ≤ N ≤ 1 000 000 (`Shard`'s own parse, shared with Python).
fn parse_shard(text: &str) -> Result<gearloss::Shard, String> {
    text.parse()
}

/// The exit code of a run stopped by Ctrl-C (128 + SIGINT, as a shell reports it).
const EXIT_INTERRUPTED: i32 = 130;

pub(crate) fn main() -> ExitCode {
    let cli = Cli::parse();
    // Ctrl-C: the report folder or scene being written is removed (never left half-written, and no
    // temporary folder beside it), then the process exits. Without a handler (a platform that has
    // none) the next run removes what is left.
    let _ = ctrlc::set_handler(|| {
        let removed = gearloss::remove_unfinished();
        errln!("interrupted: nothing was written ({removed} unfinished folder(s) or file(s) removed)");
        std::process::exit(EXIT_INTERRUPTED);
    });
    match cli.command {
        Command::Run { scene, out, shard, records } => run(&scene, &out, shard, records),
        Command::Merge { shards, out } => merge(&shards, &out),
        Command::Check { scene, emit } => check(&scene, emit.is_some()),
        Command::Import { model, out } => import(&model, out),
        Command::Render { folder } => finished(gearloss::rerender::render_into(&folder).map(|files| (folder, files))),
        Command::Units => listing(&units_table()),
        Command::Laws => listing(&gearloss::listing::laws()),
        Command::Oils => listing(&gearloss::listing::oils()),
        Command::Bearings => listing(&gearloss::listing::bearings()),
        Command::New { scene, kind } => new_scene(&scene, &kind),
    }
}

/// `gearloss import`: the scene written whole (a temporary file renamed into place, never over an
/// existing file), the warnings on stderr; nothing written on an error.
fn import(model: &Path, out: Option<PathBuf>) -> ExitCode {
    let imported = match gearloss::rexs::import_file(model) {
        Ok(i) => i,
        Err(e) => {
            for e in e.all() {
                errln!("error: {}: {e}", model.display());
                errln!("  help: {}", e.hint);
            }
            if !e.more.is_empty() {
                errln!("{} errors in {}", e.more.len() + 1, model.display());
            }
            return ExitCode::from(EXIT_SCENE);
        }
    };
    let out = out.unwrap_or_else(|| model.with_extension("gear"));
    if out.exists() {
        errln!("error: {} exists; gearloss import never overwrites a file (give another with -o)", out.display());
        return ExitCode::from(EXIT_IO);
    }
    if let Err(e) = gearloss::write_new_file(&out, imported.scene.as_bytes()) {
        errln!("error: cannot write {}: {e}", out.display());
        return ExitCode::from(EXIT_IO);
    }
    for w in &imported.warnings {
        errln!("warning: {w}");
    }
    outln!(
        "wrote {} ({} warning(s)): `gearloss check {0}`, then `gearloss run {0}`",
        out.display(),
        imported.warnings.len()
    );
    ExitCode::SUCCESS
}

fn listing(text: &str) -> ExitCode {
    say!(out, "{text}");
    ExitCode::SUCCESS
}

/// The `--kind` values of `gearloss new`, each with its help, from the templates' table.
fn template_kinds() -> clap::builder::PossibleValuesParser {
    let values = gearloss::listing::TEMPLATES.iter().map(|t| clap::builder::PossibleValue::new(t.kind).help(t.what));
    clap::builder::PossibleValuesParser::new(values)
}

/// `gearloss new [--kind K]`: the template, never over an existing file (a file the template writes
/// beside it too, unless a file of its name is there already).
fn new_scene(path: &Path, kind: &str) -> ExitCode {
    let templates = gearloss::listing::TEMPLATES;
    let template = templates.iter().find(|t| t.kind == kind).unwrap_or(&templates[0]);
    let create = |p: &Path, bytes: &[u8]| {
        let file = std::fs::OpenOptions::new().write(true).create_new(true).open(p);
        file.and_then(|mut f| std::io::Write::write_all(&mut f, bytes))
    };
    if let Err(e) = create(path, template.text.as_bytes()) {
        errln!("error: cannot write {}: {e} (gearloss new never overwrites a file)", path.display());
        return ExitCode::from(EXIT_IO);
    }
    outln!("wrote {}: edit it, then `gearloss check {0}` and `gearloss run {0}`", path.display());
    if let Some((name, bytes)) = template.beside {
        let trace = path.parent().unwrap_or(Path::new(".")).join(name);
        match create(&trace, bytes) {
            Ok(()) => outln!(
                "wrote {} beside it (the scene reads it; its source is in the scene's first lines)",
                trace.display()
            ),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                outln!(
                    "kept {}: a file of that name is there already (the scene reads it as its trace)",
                    trace.display()
                )
            }
            Err(e) => {
                errln!("error: cannot write {}: {e}", trace.display());
                return ExitCode::from(EXIT_IO);
            }
        }
    }
    ExitCode::SUCCESS
}

fn read(path: &Path) -> Result<String, ExitCode> {
    gearloss::scene::source::read_text(path, gearloss::scene::source::MAX_SCENE_BYTES).map_err(|e| {
        errln!("error: cannot read {}: {e}", path.display());
        ExitCode::from(EXIT_IO)
    })
}

fn report_errors(errors: &gearloss::SceneErrors) -> ExitCode {
    say!(err, "{}", errors.render(std::io::stderr().is_terminal()));
    ExitCode::from(EXIT_SCENE)
}

fn check(path: &Path, emit_lowered: bool) -> ExitCode {
    let source = match read(path) {
        Ok(s) => s,
        Err(code) => return code,
    };
    match gearloss::check(&path.display().to_string(), &source) {
        Ok(scene) if emit_lowered => {
            say!(out, "{}", gearloss::lowered(&scene));
            ExitCode::SUCCESS
        }
        Ok(scene) => {
            let n = scene.operating.count();
            outln!(
                "{}: scene \"{}\" is valid ({} operating point{})",
                path.display(),
                scene.title,
                n,
                if n == 1 { "" } else { "s" }
            );
            let runs = gearloss::scene::summary::would_run(&scene);
            if runs.is_empty() {
                outln!("it asks for no analysis: add an `analyses {{ ... }}` block (README lists them)");
            } else {
                outln!("`gearloss run` would compute:");
                for r in runs {
                    outln!("  - {r}");
                }
            }
            for w in gearloss::scene::summary::unused_blocks(&scene) {
                outln!("warning: {w}");
            }
            ExitCode::SUCCESS
        }
        Err(e) => report_errors(&e),
    }
}

/// A progress bar over the whole run, a stage at a time, on a terminal only.
struct Bar(Option<indicatif::ProgressBar>);

impl Bar {
    fn new() -> Bar {
        Bar(std::io::stderr().is_terminal().then(|| {
            let bar = indicatif::ProgressBar::new(0);
            if let Ok(style) = indicatif::ProgressStyle::with_template("{msg:>9} [{bar:40}] {pos}/{len} {elapsed}") {
                bar.set_style(style.progress_chars("=> "));
            }
            bar
        }))
    }
}

impl gearloss::Progress for Bar {
    fn stage(&self, label: &'static str, total: u64) {
        if let Some(bar) = &self.0 {
            bar.set_message(label);
            bar.set_length(total);
            bar.set_position(0);
        }
    }
    fn advance(&self, n: u64) {
        if let Some(bar) = &self.0 {
            bar.inc(n);
        }
    }
}

impl Drop for Bar {
    fn drop(&mut self) {
        if let Some(bar) = &self.0 {
            bar.finish_and_clear();
        }
    }
}

fn finished(result: Result<(PathBuf, Vec<String>), gearloss::RunError>) -> ExitCode {
    match result {
        Ok((dir, files)) => {
            outln!("wrote {}", dir.display());
            for file in files {
                outln!("  {file}");
            }
            ExitCode::SUCCESS
        }
        Err(gearloss::RunError::Scene(e)) => report_errors(&e),
        Err(e) => {
            errln!("error: {e}");
            for hint in e.failure().map_or(&[][..], |f| &f.hints[..]) {
                errln!("  help: {hint}");
            }
            // Shard folders that do not form one set are the user's input, as a scene is (README).
            ExitCode::from(if matches!(e, gearloss::RunError::Shards(_)) { EXIT_SCENE } else { EXIT_IO })
        }
    }
}

/// After `run` or `merge`: each drive report's headline and first warnings, then each of its stage
/// meshes' reports' (labelled by their folders), then the folder.
fn written(result: Result<gearloss::Written, gearloss::RunError>) -> ExitCode {
    match result {
        Ok(w) => {
            for (label, drive) in &w.drives {
                say!(out, "{}\n", gearloss::render::terminal::drive_summary(drive, label));
            }
            for (label, report) in &w.reports {
                say!(out, "{}\n", gearloss::render::terminal::run_summary(report, label));
            }
            outln!("wrote {} ({} files: report.md is the report)", w.folder.display(), w.files.len());
            ExitCode::SUCCESS
        }
        Err(e) => finished(Err(e)),
    }
}

fn run(path: &Path, out: &Path, shard: Option<gearloss::Shard>, records: gearloss::RecordFormats) -> ExitCode {
    let source = match read(path) {
        Ok(s) => s,
        Err(code) => return code,
    };
    let name = path.display().to_string();
    let scene = match gearloss::check(&name, &source) {
        Ok(s) => s,
        Err(e) => return report_errors(&e),
    };
    let bar = Bar::new();
    let result = gearloss::run_into_with(&name, &source, &scene, (out, shard), records, &bar);
    drop(bar);
    written(result)
}

fn merge(shards: &[PathBuf], out: &Path) -> ExitCode {
    let bar = Bar::new();
    let result = gearloss::merge_into(shards, out, &bar);
    drop(bar);
    written(result)
}

fn units_table() -> String {
    let mut out = format!("{:<6} {:<24} {:>24} {:<16} {}\n", "unit", "quantity", "in SI", "SI unit", "equals");
    for u in gearloss::scene::units::UNITS {
        let equals = match u.composition {
            Some((1.0, expr)) => expr.to_string(),
            Some((k, expr)) => format!("{k} {expr}"),
            None => String::new(),
        };
        let si = match (u.offset != 0.0, u.factor == 1.0) {
            (true, true) => format!("x + {}", u.offset),
            (true, false) => format!("{:.6} x + {:.4}", u.factor, u.offset),
            (false, _) => format!("{:e}", u.factor),
        };
        out.push_str(&format!(
            "{:<6} {:<24} {:>24} {:<16} {}\n",
            u.name,
            u.quantity(),
            si,
            u.dimension.si_unit(),
            equals
        ));
    }
    out.push_str("\nCompound units multiply and divide these: N*m, lbf*in, kg*m^2, lbf*s^2*in, 1/Pa, mm^2/s, N/um.\n");
    out
}
