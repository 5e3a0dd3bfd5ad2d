//! `hawser validate`: runs the verification suite (`hawser::verification`), prints one row per
//! case, formulation and (for the cases that step in time) scheme, writes the markdown report with its plots
//! (`hawser_io::verification_report`) and exits 1 when any check fails.

use anyhow::{Context, Result, bail};
use hawser::model::{Formulation, Scheme};
use hawser::verification::{CASES, Fidelity, run_case, run_label};
use hawser_io::verification_report::{tally, text_table, write_report};
use rayon::prelude::*;
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
    /// Time-integration schemes of the cases that step in time, comma-separated: `rk4`,
    /// `generalized-alpha` (the others are statics and run once).
    #[arg(long, value_delimiter = ',', default_value = "rk4")]
    scheme: Vec<String>,
    /// Rows run at a time, one per thread (default: every core). The rows are independent
    /// runs; the table and the report list them in the suite's order whatever finishes first.
    #[arg(long)]
    jobs: Option<std::num::NonZeroUsize>,
}

fn parse_scheme(name: &str) -> Result<Scheme> {
    Ok(match name.trim() {
        "rk4" => Scheme::Rk4,
        "generalized-alpha" => Scheme::GeneralizedAlpha,
        other => bail!(
            "unknown scheme `{other}` for validate (expected rk4 or generalized-alpha; the \
             suite's cases state their steps and tolerances for these two)"
        ),
    })
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
    let schemes = args
        .scheme
        .iter()
        .map(|s| parse_scheme(s))
        .collect::<Result<Vec<_>>>()?;
    let fidelity = if args.quick {
        Fidelity::Quick
    } else {
        Fidelity::Full
    };
    let jobs = crate::jobs_or_cores(args.jobs);
    // Every (case, formulation, scheme) row of the selection, in the suite's order.
    let mut rows = Vec::new();
    for case in CASES {
        if let Some(filter) = &args.case
            && !case.name.contains(filter.as_str())
        {
            continue;
        }
        let case_schemes = if case.steps_in_time {
            &schemes[..]
        } else {
            &schemes[..1]
        };
        for &f in &formulations {
            for &scheme in case_schemes {
                rows.push((case, f, scheme));
            }
        }
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs)
        .build()
        .context("cannot start the threads of the suite")?;
    let start = Instant::now();
    // rayon's collect keeps the rows' order; each row's time is printed as it finishes.
    let results: Vec<_> = pool.install(|| {
        rows.par_iter()
            .map(|&(case, f, scheme)| {
                let t = Instant::now();
                let r = run_case(case, f, fidelity, scheme);
                err!(
                    "{} ({}): {:.1} s",
                    case.name,
                    run_label(f, r.scheme),
                    t.elapsed().as_secs_f64()
                );
                r
            })
            .collect()
    });
    let wall = start.elapsed().as_secs_f64();
    let checks: Vec<_> = results.iter().flat_map(|r| &r.checks).collect();
    out!("{}", text_table(&checks).trim_end_matches('\n'));
    let (pass, fail, na) = tally(&results);
    out!(
        "\n{pass} passed, {fail} failed, {na} not available ({} suite, {wall:.1} s)",
        if args.quick { "quick" } else { "full" }
    );
    if !args.no_report {
        let names: Vec<&str> = formulations
            .iter()
            .map(|&f| hawser::verification::formulation_name(f))
            .collect();
        let scheme_names: Vec<&str> = schemes.iter().map(|s| s.name()).collect();
        let preamble = format!(
            "Produced by `hawser validate{}{}{}` ({} suite, formulations {}, schemes {}; \
             {wall:.0} s wall time in release mode). Regenerate with\n\n```sh\ncargo run \
             --release -p hawser-cli -- validate{}\n```\n\nfrom the repository root (writes this \
             file and `img/`).",
            if args.quick { " --quick" } else { "" },
            if names.len() == 3 {
                String::new()
            } else {
                format!(" --formulation {}", names.join(","))
            },
            if scheme_names == ["rk4"] {
                String::new()
            } else {
                format!(" --scheme {}", scheme_names.join(","))
            },
            if args.quick { "quick" } else { "full" },
            names.join(", "),
            scheme_names.join(", "),
            if scheme_names == ["rk4"] {
                String::new()
            } else {
                format!(" --scheme {}", scheme_names.join(","))
            },
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
