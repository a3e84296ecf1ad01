//! TypeScript types of the option and result objects (the Result keys of methods.md),
//! added to the generated `.d.ts` by concern; checked by `tsc --noEmit` in the tests.

mod evaluation;
mod import;
mod log;
mod methods;
mod tune;
mod view;
