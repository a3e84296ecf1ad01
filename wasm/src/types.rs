//! TypeScript types of the option and result objects (the Result keys of methods.md),
//! added to the generated `.d.ts` by concern; checked by `tsc --noEmit` in the tests.
//! The chart module (`plot` alone) declares only the chart types: the others name `Log`,
//! which that module does not have.

#[cfg(feature = "core")]
mod evaluation;
#[cfg(feature = "core")]
mod import;
#[cfg(feature = "core")]
mod log;
#[cfg(feature = "core")]
mod methods;
#[cfg(feature = "core")]
mod tune;
mod view;
