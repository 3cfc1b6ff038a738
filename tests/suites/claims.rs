//! The paper's claims and the documents: every claim, the proofs' index, the coverage of the catalogue, the math of the docs, the errata, the layers of `src/`, the quickcheck identities.
//!
//! One test binary of several files (docs/testing.md, "Test binaries"); each file is a
//! module, its tests named `file::test`.

#[path = "../common/mod.rs"]
mod common;

#[path = "../claims/mod.rs"]
mod claims;
#[path = "../claims_index.rs"]
mod claims_index;
#[path = "../coverage.rs"]
mod coverage;
#[path = "../doc_math.rs"]
mod doc_math;
#[path = "../errata.rs"]
mod errata;
#[path = "../layers.rs"]
mod layers;
#[path = "../public_api.rs"]
mod public_api;
#[path = "../quickcheck_identities.rs"]
mod quickcheck_identities;
