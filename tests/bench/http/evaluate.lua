-- wrk script: POST /evaluate, one cubic at one t.
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"
wrk.body = '{"points":[[0,0],[1,2],[3,3],[4,0]],"t":0.5}'
