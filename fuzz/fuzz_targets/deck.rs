//! The MoorDyn deck reader with the converter and a round trip through TOML
//! (hawser_io::fuzzing::deck_bytes).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| hawser_io::fuzzing::deck_bytes(data));
