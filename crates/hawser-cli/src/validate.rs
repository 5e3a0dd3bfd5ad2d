//! `hawser validate`: runs the verification suite (`hawser::verification`), prints one row per
//! case and formulation, writes the markdown report with its plots
//! (`hawser_io::verification_report`) and exits 1 when any check fails.

use anyhow::{Context, Result, bail};
use hawser::model::Formulation;
use hawser::verification::{CASES, Fidelity, formulation_name, run_case};
use hawser_io::verification_report::{tally, text_table, write_report};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

/// Arguments of `hawser validate`.
#[derive(clap::Args)]
pub struct ValidateArgs {
    /// Run the quick subset (CI): the same checks on the tests' meshes and durations.
    #[arg(long)]
    quick: bool,
    /// Formulations to run, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "fe,hermite,dg")]
    formulation: Vec<String>,
    /// Where to write the markdown report (its plots go to `img/` beside it).
    #[arg(long, default_value = "docs/verification/report.md")]
    report: PathBuf,
    /// Do not write the report.
    #[arg(long, conflicts_with = "report")]
    no_report: bool,
    /// Run only the cases whose name contains this text.
    #[arg(long)]
    case: Option<String>,
}

fn parse_formulation(name: &str) -> Result<Formulation> {
    Ok(match name.trim() {
        "fe" => Formulation::Fe,
        "hermite" => Formulation::Hermite,
        "dg" => Formulation::Dg,
        other => bail!("unknown formulation `{other}` (expected fe, hermite or dg)"),
    })
}

/// Runs the suite.
pub fn run(args: &ValidateArgs) -> Result<ExitCode> {
    let formulations = args
        .formulation
        .iter()
        .map(|f| parse_formulation(f))
        .collect::<Result<Vec<_>>>()?;
    let fidelity = if args.quick {
        Fidelity::Quick
    } else {
        Fidelity::Full
    };
    let start = Instant::now();
    let mut results = Vec::new();
    for case in CASES {
        if let Some(filter) = &args.case
            && !case.name.contains(filter.as_str())
        {
            continue;
        }
        for &f in &formulations {
            let t = Instant::now();
            let r = run_case(case, f, fidelity);
            err!(
                "{} ({}): {:.1} s",
                case.name,
                formulation_name(f),
                t.elapsed().as_secs_f64()
            );
            results.push(r);
        }
    }
    let wall = start.elapsed().as_secs_f64();
    let checks: Vec<_> = results.iter().flat_map(|r| &r.checks).collect();
    out!("{}", text_table(&checks).trim_end_matches('\n'));
    let (pass, fail, na) = tally(&results);
    out!(
        "\n{pass} passed, {fail} failed, {na} not available ({} suite, {wall:.1} s)",
        if args.quick { "quick" } else { "full" }
    );
    if !args.no_report {
        let names: Vec<&str> = formulations.iter().map(|&f| formulation_name(f)).collect();
        let preamble = format!(
            "Produced by `hawser validate{}{}` ({} suite, formulations {}; {wall:.0} s wall \
             time in release mode). Regenerate with\n\n```sh\ncargo run --release -p hawser-cli \
             -- validate\n```\n\nfrom the repository root (writes this file and `img/`).",
            if args.quick { " --quick" } else { "" },
            if names.len() == 3 {
                String::new()
            } else {
                format!(" --formulation {}", names.join(","))
            },
            if args.quick { "quick" } else { "full" },
            names.join(", ")
        );
        write_report(&results, &args.report, &preamble)
            .with_context(|| format!("writing {}", args.report.display()))?;
        out!("report: {}", args.report.display());
    }
    Ok(if fail > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
