//! The TOML scenario reader with the builder (hawser_io::fuzzing::scenario_bytes).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| hawser_io::fuzzing::scenario_bytes(data));
