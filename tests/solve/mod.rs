mod furnace;
