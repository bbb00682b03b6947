mod assembly;
mod cells;
mod forecast;
mod form_factor;
mod memory_limit;
mod peak;
mod precision;
