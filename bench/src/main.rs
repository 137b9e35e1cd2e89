//! `autostereo-bench`: the benchmark harness (bench/src/lib.rs), a binary of its own so that
//! the user's `autostereo` keeps no bench code.

use clap::Parser;

/// Benchmark every renderer side by side, with speed/accuracy trade-offs (`--report DIR`).
#[derive(Parser)]
#[command(name = "autostereo-bench", version, after_help = autostereo_bench::EXAMPLES)]
struct Cli {
    #[command(flatten)]
    args: autostereo_bench::BenchArgs,
}

fn main() -> std::process::ExitCode {
    // wgpu probes EGL displays and logs their failures as errors even when Vulkan is used.
    env_logger::Builder::from_env(
        env_logger::Env::default()
            .default_filter_or("warn,autostereo=info,wgpu_hal::gles::egl=off"),
    )
    .format_timestamp(None)
    .init();
    match autostereo_bench::run(Cli::parse().args) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
