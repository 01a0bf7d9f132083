/*  Tests of the HTTP side (prolog/oro/http/oro_http.pl): the SPARQL 1.1
    Protocol endpoint at /sparql, by real HTTP requests on a server of
    an ephemeral loopback port, in the ways SPARQL clients send them:
    rdflib's SPARQLWrapper (GET, or POST of a form, Accept naming one
    type), Jena's rsparql (GET with a weighted Accept list) and a POST
    of the query itself (application/sparql-query); the command line's
    --http option; Pengines from a second swipl process.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(http/http_open)).
:- use_module(library(http/json)).
:- use_module(library(readutil)).
:- use_module(library(process)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(uri)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro)).
:- use_module('../server/oro_server').

%   hp_start: the unit's server, with its HTTP side on a free port, on
%   the test ontology and two facts of our own.

hp_start :-
    test_server_start_testsuite([http(0)]),
    oro_add(myself, ["zork grams 50", "zork rdf:type Monkey",
                     "zork label \"Zork, the \\\"big\\\" one\"@en"]).

%   hp_request(+Path, +How, +Accept, -Status, -Type, -Body): one HTTP
%   request to the unit's server.  How is get(Params), form(Params) or
%   body(ContentType, Text, Params) (Params in the URL).

hp_request(Path, How, Accept, Status, Type, Body) :-
    test_server_http_port(Port),
    how_params(How, Params),
    uri_query_components(Search, Params),
    format(atom(URL), 'http://127.0.0.1:~w~w?~w', [Port, Path, Search]),
    how_options(How, Options0),
    (   Accept == none
    ->  Options1 = Options0
    ;   Options1 = [request_header('Accept'=Accept)|Options0]
    ),
    setup_call_cleanup(
        http_open(URL, In, [ status_code(Status),
                             header(content_type, Type),
                             timeout(30)
                           | Options1
                           ]),
        ( set_stream(In, encoding(utf8)),
          read_string(In, _, Body)
        ),
        close(In)).

how_params(get(Ps), Ps).
how_params(form(_), []).
how_params(body(_, _, Ps), Ps).

how_options(get(_), []).
how_options(form(Ps), [method(post), post(form(Ps))]).
how_options(body(Type, Text, _), [method(post), post(codes(Type, Codes))]) :-
    string_codes(Text, Codes).

sparql_json(Body, Dict) :-
    atom_json_dict(Body, Dict, []).

%   hp_select_values(+Query, +Params, -Values): the values of ?x in the
%   JSON result of Query, sorted.

hp_select_values(Query, Params, Values) :-
    hp_request('/sparql', get([query=Query|Params]),
               'application/sparql-results+json', 200, _, Body),
    sparql_json(Body, Dict),
    findall(V, ( member(B, Dict.results.bindings), V = B.x.value ), Vs),
    msort(Vs, Values).

testsuite_url(URL) :-
    test_fixture('testsuite.ttl', File),
    uri_file_name(URL, File).

:- begin_tests(http_sparql_protocol, [setup(hp_start), cleanup(test_server_stop)]).

test(get_json_ask, [true(Answer == [200, 'application/sparql-results+json; charset=UTF-8', true])]) :-
    hp_request('/sparql', get([query="ASK { ?x a <http://kb.openrobots.org#Monkey> }"]),
               'application/sparql-results+json', Status, Type, Body),
    sparql_json(Body, Dict),
    Answer = [Status, Type, Dict.boolean].

test(get_json_select_head_in_projection_order, [true(Vars == ["w", "x"])]) :-
    hp_request('/sparql', get([query="SELECT ?w ?x WHERE { ?x oro:grams ?w }"]),
               'application/sparql-results+json', 200, _, Body),
    sparql_json(Body, Dict),
    Vars = Dict.head.vars.

test(any_type_is_json, [true(Type == 'application/sparql-results+json; charset=UTF-8')]) :-
    hp_request('/sparql', get([query="ASK {}"]), '*/*', 200, Type, _).

test(no_accept_is_json, [true(Type == 'application/sparql-results+json; charset=UTF-8')]) :-
    hp_request('/sparql', get([query="ASK {}"]), none, 200, Type, _).

test(jena_weighted_accept, [true(Type == 'application/sparql-results+json; charset=UTF-8')]) :-
    hp_request('/sparql', get([query="SELECT * WHERE { ?x a oro:Monkey }"]),
               'application/sparql-results+json, application/sparql-results+xml;q=0.9, text/tab-separated-values;q=0.7, text/csv;q=0.5, application/json;q=0.2, application/xml;q=0.2, */*;q=0.1',
               200, Type, _).

test(weights_pick_tsv, [true(Type == 'text/tab-separated-values; charset=UTF-8')]) :-
    hp_request('/sparql', get([query="ASK {}"]),
               'text/csv;q=0.5, text/tab-separated-values', 200, Type, _).

test(sparqlwrapper_post_form, [true(Status-Values == 200-["http://kb.openrobots.org#zork"])]) :-
    hp_request('/sparql', form([query="SELECT ?x WHERE { ?x oro:grams 50 }"]),
               'application/sparql-results+json', Status, _, Body),
    sparql_json(Body, Dict),
    findall(V, ( member(B, Dict.results.bindings), V = B.x.value ), Values).

test(post_query_body, [true(Status-Body == 200-"?x\n<http://kb.openrobots.org#zork>\n")]) :-
    hp_request('/sparql',
               body('application/sparql-query', "SELECT ?x WHERE { ?x oro:grams ?w }", []),
               'text/tab-separated-values', Status, _, Body).

test(xml_select, [true(Body == Expected)]) :-
    hp_request('/sparql', get([query="SELECT ?x ?l WHERE { ?x oro:label ?l }"]),
               'application/sparql-results+xml', 200, _, Body),
    Expected = "<?xml version=\"1.0\"?>\n<sparql xmlns=\"http://www.w3.org/2005/sparql-results#\">\n  <head>\n    <variable name=\"x\"/>\n    <variable name=\"l\"/>\n  </head>\n  <results>\n    <result>\n      <binding name=\"x\"><uri>http://kb.openrobots.org#zork</uri></binding>\n      <binding name=\"l\"><literal xml:lang=\"en\">Zork, the &quot;big&quot; one</literal></binding>\n    </result>\n  </results>\n</sparql>\n".

test(csv_select, [true(Body == "x,l\r\nhttp://kb.openrobots.org#zork,\"Zork, the \"\"big\"\" one\"\r\n")]) :-
    hp_request('/sparql', get([query="SELECT ?x ?l WHERE { ?x oro:label ?l }"]),
               'text/csv', 200, _, Body).

test(tsv_select_typed, [true(Body == "?x\t?w\n<http://kb.openrobots.org#zork>\t\"50\"^^<http://www.w3.org/2001/XMLSchema#int>\n")]) :-
    hp_request('/sparql', get([query="SELECT ?x ?w WHERE { ?x oro:grams ?w }"]),
               'text/tab-separated-values', 200, _, Body).

test(format_parameter, [true(Type == 'text/csv; charset=UTF-8')]) :-
    hp_request('/sparql', get([query="ASK {}", format=csv]), 'application/json', 200, Type, _).

test(unacceptable_406, [true(Status == 406)]) :-
    hp_request('/sparql', get([query="ASK {}"]), 'image/png', Status, _, _).

test(syntax_error_400, [true(Status-Type-Found == 400-'text/plain; charset=UTF-8'-true)]) :-
    hp_request('/sparql', get([query="SELEC ?x"]), 'application/sparql-results+json',
               Status, Type, Body),
    test_bool(sub_string(Body, _, _, _, "Line 1, column 1"), Found).

test(no_query_400, [true(Status == 400)]) :-
    hp_request('/sparql', get([]), none, Status, _, _).

test(two_queries_400, [true(Status == 400)]) :-
    hp_request('/sparql', get([query="ASK {}", query="ASK {}"]), none, Status, _, _).

test(update_refused, [true(Answer == [403, 403, 400, Count])]) :-
    oro_sparql(myself, "SELECT (COUNT(*) AS ?n) WHERE { ?s ?p ?o }", R0, [infer(false)]),
    R0 = select(_, [[n-literal(type(_, Count))]]),
    hp_request('/sparql', form([update="INSERT DATA { <a:a> <a:b> <a:c> }"]), none, S1, _, _),
    hp_request('/sparql', body('application/sparql-update',
                               "DELETE WHERE { ?s ?p ?o }", []), none, S2, _, _),
    hp_request('/sparql', get([query="INSERT DATA { <a:a> <a:b> <a:c> }"]), none, S3, _, _),
    oro_sparql(myself, "SELECT (COUNT(*) AS ?n) WHERE { ?s ?p ?o }", R1, [infer(false)]),
    R1 = select(_, [[n-literal(type(_, Count1))]]),
    Answer = [S1, S2, S3, Count1].

test(infer_false_asserted_only, [true(Answer == [["http://kb.openrobots.org#zork"], []])]) :-
    % zork is an Animal by the class hierarchy only
    hp_select_values("SELECT ?x WHERE { ?x a oro:Animal ; oro:grams ?w }", [], A1),
    hp_select_values("SELECT ?x WHERE { ?x a oro:Animal ; oro:grams ?w }", [infer=false], A2),
    Answer = [A1, A2].

test(default_graph_is_the_file, [true(Answer == [Count, false, true])]) :-
    testsuite_url(URL),
    oro_sparql_graph(URL, Graph),
    rdf_graph_property(Graph, triples(Count)),
    hp_request('/sparql', get([query="SELECT (COUNT(*) AS ?n) WHERE { ?s ?p ?o }",
                               'default-graph-uri'=URL, infer=false]),
               'application/sparql-results+json', 200, _, Body),
    sparql_json(Body, Dict),
    Dict.results.bindings = [B],
    number_string(Count1, B.n.value),
    hp_request('/sparql', get([query="ASK { oro:myself a ?c }",
                               'default-graph-uri'=URL, infer=false]),
               'application/sparql-results+json', 200, _, Body2),
    sparql_json(Body2, Dict2),
    hp_request('/sparql', get([query="ASK { oro:myself a ?c }", infer=false]),
               'application/sparql-results+json', 200, _, Body3),
    sparql_json(Body3, Dict3),
    Count1 =:= Count,
    Answer = [Count1, Dict2.boolean, Dict3.boolean].

test(bad_infer_400, [true(Status == 400)]) :-
    hp_request('/sparql', get([query="ASK {}", infer=maybe]), none, Status, _, _).

test(agent_model, [true(Answer == [["http://kb.openrobots.org#banana"], []])]) :-
    oro_create_agent(bob, bob),
    oro_add(bob, ["banana rdf:type Fruit"]),
    hp_select_values("SELECT ?x WHERE { ?x a oro:Fruit }", [], Mine),
    hp_request('/sparql/bob', get([query="SELECT ?x WHERE { ?x a oro:Fruit }"]),
               'application/sparql-results+json', 200, _, Body),
    sparql_json(Body, Dict),
    findall(V, ( member(B, Dict.results.bindings), V = B.x.value ), Bobs),
    Answer = [Bobs, Mine].

test(unknown_agent_404, [true(Status == 404)]) :-
    hp_request('/sparql/nobody_here', get([query="ASK {}"]), none, Status, _, _).

test(graphs_page, [true(Found == true)]) :-
    testsuite_url(URL),
    hp_request('/graphs', get([]), 'text/html', 200, _, Body),
    test_bool(( sub_string(Body, _, _, _, URL),
                sub_string(Body, _, _, _, "oro:myself#longterm")
              ), Found).


test(construct_ntriples, [true(Answer == ['application/n-triples; charset=UTF-8', Expected])]) :-
    hp_request('/sparql', get([query="CONSTRUCT { ?x oro:heavy ?w . _:b oro:of ?x } WHERE { ?x oro:grams ?w }"]),
               'application/n-triples', 200, Type, Body),
    Expected = "_:c1b_5f_b <http://kb.openrobots.org#of> <http://kb.openrobots.org#zork> .\n<http://kb.openrobots.org#zork> <http://kb.openrobots.org#heavy> \"50\"^^<http://www.w3.org/2001/XMLSchema#int> .\n",
    Answer = [Type, Body].

test(construct_any_type_is_turtle, [true(Answer == ['text/turtle; charset=UTF-8', Expected])]) :-
    hp_request('/sparql', get([query="CONSTRUCT WHERE { ?x oro:grams ?w ; a ?c }", infer=false]),
               '*/*', 200, Type, Body),
    Expected = "<http://kb.openrobots.org#zork>\n    <http://kb.openrobots.org#grams> \"50\"^^<http://www.w3.org/2001/XMLSchema#int> ;\n    <http://www.w3.org/1999/02/22-rdf-syntax-ns#type> <http://kb.openrobots.org#Monkey> .\n",
    Answer = [Type, Body].

test(construct_json_406, [true(Status == 406)]) :-
    hp_request('/sparql', get([query="CONSTRUCT WHERE { ?x oro:grams ?w }"]),
               'application/sparql-results+json', Status, _, _).

test(describe, [true(Body == Expected)]) :-
    hp_request('/sparql', get([query="DESCRIBE ?x WHERE { ?x oro:grams ?w }", infer=false]),
               'application/n-triples', 200, _, Body),
    Expected = "<http://kb.openrobots.org#zork> <http://kb.openrobots.org#grams> \"50\"^^<http://www.w3.org/2001/XMLSchema#int> .\n<http://kb.openrobots.org#zork> <http://kb.openrobots.org#label> \"Zork, the \\\"big\\\" one\"@en .\n<http://kb.openrobots.org#zork> <http://www.w3.org/1999/02/22-rdf-syntax-ns#type> <http://kb.openrobots.org#Monkey> .\n".

test(graph_over_named_graphs, [true(Answer == ["oro:myself#longterm"-"http://kb.openrobots.org#zork", []])]) :-
    testsuite_url(URL),
    hp_request('/sparql', get([query="SELECT ?g ?x WHERE { GRAPH ?g { ?x oro:grams ?w } }"]),
               'application/sparql-results+json', 200, _, Body),
    sparql_json(Body, Dict),
    findall(G-X, ( member(B, Dict.results.bindings), G = B.g.value, X = B.x.value ), [Pair]),
    hp_request('/sparql', get([query="SELECT ?g ?x WHERE { GRAPH ?g { ?x oro:grams ?w } }",
                               'named-graph-uri'=URL]),
               'application/sparql-results+json', 200, _, Body2),
    sparql_json(Body2, Dict2),
    Answer = [Pair, Dict2.results.bindings].

%   A sub-select inside GRAPH ?g has one table per named graph (it was
%   computed once, in the first graph, and reused for every other).

test(subselect_per_named_graph, [true(Answer == ["1", true])]) :-
    hp_request('/sparql', get([query="SELECT ?g ?n WHERE { GRAPH ?g { SELECT (COUNT(*) AS ?n) WHERE { ?x oro:grams ?w } } }"]),
               'application/sparql-results+json', 200, _, Body),
    sparql_json(Body, Dict),
    findall(G-N, ( member(B, Dict.results.bindings),
                   G = B.g.value, N = B.n.value ), Pairs),
    memberchk("oro:myself#longterm"-N1, Pairs),
    (   forall(member(G-N, Pairs), ( G == "oro:myself#longterm" ; N == "0" )),
        Pairs = [_, _|_]
    ->  Others = true
    ;   Others = false
    ),
    Answer = [N1, Others].

test(from_file_graph, [true(Answer == [false, true])]) :-
    testsuite_url(URL),
    format(string(Q1), "ASK FROM <~w> { oro:zork ?p ?o }", [URL]),
    format(string(Q2), "ASK FROM <~w> { oro:baboon ?p ?o }", [URL]),
    hp_request('/sparql', get([query=Q1]), 'application/sparql-results+json', 200, _, B1),
    hp_request('/sparql', get([query=Q2]), 'application/sparql-results+json', 200, _, B2),
    sparql_json(B1, D1),
    sparql_json(B2, D2),
    Answer = [D1.boolean, D2.boolean].

test(oro_sparql_method_refuses_construct, [error(syntax_error(oro_sparql(_, 0)))]) :-
    oro_sparql_json(myself, "CONSTRUCT WHERE { ?x oro:grams ?w }", _).

:- end_tests(http_sparql_protocol).

		 /*******************************
		 *           PENGINES           *
		 *******************************/

%   pengine_client(-Answers): the answers of test/fixtures/pengine_client.pl,
%   a second swipl process asking the unit's server.

pengine_client(Answers) :-
    test_server_http_port(Port),
    format(atom(URL), 'http://127.0.0.1:~w', [Port]),
    test_checkout_path('test/fixtures/pengine_client.pl', File),
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl, File, URL],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_term(Out, Answers, []),
          process_wait(Pid, Status)
        ),
        close(Out)),
    assertion(Status == exit(0)).

:- begin_tests(http_pengines, [setup(hp_start), cleanup(test_server_stop)]).

test(read_only, [true(Answer == [Find, permission, sandbox, false, true])]) :-
    pengine_client(answers(Find0, error(Change), error(Unsafe), Check)),
    oro_find(myself, x, ["?x rdf:type Monkey"], Find1),
    maplist(atom_string, Find0, Strings),
    maplist(atom_string, Find1, Strings1),
    msort(Strings, Find),
    msort(Strings1, Find),
    Find \== [],
    (   Change = permission_error(modify, oro_store, _)
    ->  C = permission
    ;   C = Change
    ),
    (   Unsafe = permission_error(call, sandboxed, _)
    ->  U = sandbox
    ;   U = Unsafe
    ),
    test_bool(oro_check(myself, ["intruder rdf:type Monkey"]), Added),
    Answer = [Find, C, U, Added, Check].

test(changes_allowed, [true(Answer == [done, true])]) :-
    test_with_setting(oro_http_pengines:changes, true,
                      pengine_client(answers(_, Change, _, _))),
    test_bool(oro_check(myself, ["intruder rdf:type Monkey"]), Added),
    Answer = [Change, Added].

:- end_tests(http_pengines).

		 /*******************************
		 *         COMMAND LINE         *
		 *******************************/

:- begin_tests(http_command_line).

test(announces_and_answers, [true(Answer == [true, true])]) :-
    test_checkout_path('server/oro_server.pl', Server),
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl, Server, '--port=0', '--http=0',
                                       '--no-commonsense'],
                       [stdout(pipe(Out)), stderr(null), process(Pid)]),
        ( read_line_to_string(Out, _),
          read_line_to_string(Out, Line),
          split_string(Line, ":", "/", Parts),
          last(Parts, PortText),
          number_string(Port, PortText),
          format(string(Expected), "oro web listening on http://127.0.0.1:~w/", [Port]),
          test_bool(Line == Expected, Exact),
          format(atom(URL), 'http://127.0.0.1:~w/sparql?query=ASK%7B%3Fx%20a%20%3Chttp%3A%2F%2Fkb.openrobots.org%23Robot%3E%7D', [Port]),
          setup_call_cleanup(
              http_open(URL, In, [request_header('Accept'='application/sparql-results+json'),
                                  timeout(30)]),
              read_string(In, _, Body),
              close(In)),
          test_bool(Body == "{\"head\":{},\"boolean\":true}", Ok),
          Answer = [Exact, Ok]
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          close(Out)
        )).

:- end_tests(http_command_line).
