vim.api.nvim_create_autocmd({ "BufReadPost" }, { pattern = "*.pov", callback = function(args)
  local id = vim.lsp.start_client({ name = "durer", cmd = { vim.env.DURER, "lsp" }, root_dir = vim.fn.getcwd() })
  vim.lsp.buf_attach_client(args.buf, id)
end })
vim.api.nvim_create_autocmd("DiagnosticChanged", { callback = function()
  local d = vim.diagnostic.get()
  if #d > 0 then
    io.stdout:write("diagnostic line " .. (d[1].lnum + 1) .. ": " .. d[1].message:gsub("\n.*", "") .. "\n")
    vim.cmd("qall!")
  end
end })
vim.defer_fn(function() io.stdout:write("no diagnostic\n"); vim.cmd("qall!") end, 15000)
