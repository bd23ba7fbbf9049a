-- wrk script: GET /healthz (the cheapest route: the HTTP layer's own ceiling).
wrk.method = "GET"
