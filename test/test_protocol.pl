:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(filesex)).
:- use_module(library(readutil)).
:- use_module(library(settings)).
:- use_module(library(aggregate)).
:- use_module(library(oro/oro_store), [oro_store_sizes/1]).
:- use_module(library(oro), [oro_class/2, oro_individual/2]).

/*  End-to-end tests of the ORO server over real sockets on 127.0.0.1:
    the test vectors of ORO-SPEC §13 (framing and dispatch §13.1, check
    §13.2, find §13.3, counts §13.4, lookup §13.6, taxonomy §13.7,
    descriptions §13.8, administration §6.7, the seed session §13.13),
    bad input, concurrent clients and the replay of a recorded robot
    session (../shared/workloads/robot-session-2011.log, if present).

    The server and its knowledge base are process-wide singletons, so
    every unit starts one server (port 0) in its setup and stops it in
    its cleanup; tests that change the store start with the `reset`
    method (srv_fresh/0).  Every socket wait is bounded (the test client
    times out after 10 seconds).

    Run: cd /work/main && swipl -g run_tests -t halt test/test_protocol.pl
*/

:- dynamic
    srv_save_dir/1,                     % Dir
    srv_replay_conn/2.                  % Thread, Conn

                 /*******************************
                 *     SERVER AND CONNECTIONS   *
                 *******************************/

%   srv_start(+Options), srv_stop: the unit's server
%   (test_server_start/1, test_server_stop/0).

srv_start(Options) :-
    test_server_start(Options).

srv_stop :-
    test_server_stop.

%   The test configuration of ORO-SPEC §13: the test ontology alone.

srv_start_testsuite :-
    test_server_start_testsuite.

%   The bundled common-sense ontology (the seed session).

srv_start_commonsense :-
    test_server_start([commonsense(true)]).

%   srv_fresh: back to the state the server started in.

srv_fresh :-
    test_ok(reset, []).

%   srv_store_state(-State): what the robot's model holds, as the
%   sorted subjects, predicates and objects of its statements.

srv_store_state(s(Ss, Ps, Os)) :-
    test_set_call(find, [s, '[?s ?p ?o]'], Ss),
    test_set_call(find, [p, '[?s ?p ?o]'], Ps),
    test_set_call(find, [o, '[?s ?p ?o]'], Os).

%   srv_reply_kind(+Reply, -Kind): ok, error or what else came.

srv_reply_kind(ok(_), ok) :- !.
srv_reply_kind(error(_, _), error) :- !.
srv_reply_kind(Other, Other).


                 /*******************************
                 *        READING VALUES        *
                 *******************************/

srv_keys(Reply, Keys) :-
    test_map(Reply, Pairs),
    pairs_keys(Pairs, Keys).

%   Small tests on values, for include/3, exclude/3 and maplist/3.

srv_string_value(_-Value) :-
    string(Value).

srv_value_of(Pairs, Key, Value) :-
    memberchk(Key-Value, Pairs).

srv_digit_shape(Code, Shape) :-
    (   code_type(Code, digit)
    ->  Shape = 0'9
    ;   Shape = Code
    ).

srv_description(_-Description) :-
    string(Description),
    Description \== "".

%   srv_contains(+Text, +Part, -Found): Found is true or missing(Part).

srv_contains(Text, Part, Found) :-
    (   sub_string(Text, _, _, _, Part)
    ->  Found = true
    ;   Found = missing(Part)
    ).

srv_about_baboon(Statement) :-
    sub_string(Statement, 0, _, _, "baboon ").

srv_snapshot_file(File) :-
    sub_atom(File, _, _, 0, '-snapshot.owl').

srv_unparsed(bad(_)).

srv_map_call(Method, Params, Pairs) :-
    test_call(Method, Params, Reply),
    test_map(Reply, Pairs).


                 /*******************************
                 *     FRAMING AND DISPATCH     *
                 *******************************/

:- begin_tests(srv_dispatch,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

test(hello, true(Reply == ok("\"oro-server 0.8.2\""))) :-
    test_call(hello, [], Reply).
test(stats_keys, true(Missing == [])) :-
    test_call(stats, [], Reply),
    srv_keys(Reply, Keys),
    subtract([ "host", "nb_classes", "nb_clients", "nb_instances",
               "pending_requests", "uptime", "version", "triples",
               "triples.ontology", "triples.myself.longterm", "models",
               "watchers", "memory_bytes"
             ], Keys, Missing).
test(stats_values_are_strings, true(NotStrings == [])) :-
    srv_map_call(stats, [], Pairs),
    exclude(srv_string_value, Pairs, NotStrings).

%   The figures that were "not available" in ORO are real counts, in
%   strings: the classes and individuals of the robot's model, the
%   connections (this one at least).

test(stats_real_figures,
     true(Figures == ["0.8.2", Classes, Instances, Longterm, true])) :-
    srv_map_call(stats, [], Pairs),
    maplist(srv_value_of(Pairs),
            ["version", "nb_classes", "nb_instances",
             "triples.myself.longterm", "nb_clients"],
            [Version, Classes0, Instances0, Longterm0, Clients]),
    aggregate_all(count, oro_class(myself, _), NClasses),
    aggregate_all(count, oro_individual(myself, _), NInstances),
    oro_store_sizes(Sizes),
    memberchk(size(myself, profile(longterm), NLongterm), Sizes),
    maplist(number_string, [NClasses, NInstances, NLongterm],
            [Classes, Instances, Longterm]),
    number_string(NClients, Clients),
    test_bool(NClients >= 1, AtLeastOne),
    Figures = [Version, Classes0, Instances0, Longterm0, AtLeastOne].
test(stats_uptime_format, true(Shape == "99:99:99")) :-
    srv_map_call(stats, [], Pairs),
    memberchk("uptime"-Uptime, Pairs),
    string_codes(Uptime, Codes),
    maplist(srv_digit_shape, Codes, Shape0),
    string_codes(Shape, Shape0).
test(simple_methods_format, true(Malformed == [])) :-
    test_set_call(listSimpleMethods, [], Signatures),
    exclude(srv_signature, Signatures, Malformed).
test(simple_methods_core,
     true(Missing == [])) :-
    test_set_call(listSimpleMethods, [], Signatures),
    subtract(["add(Set)", "find(String, Set)", "check(Set)", "hello()",
              "stats()", "listSimpleMethods()", "reset()", "clear()",
              "clear(Set)", "lookup(String)", "getLabel(String)"],
             Signatures, Missing).
test(unimplemented_not_listed, true(Bad == [])) :-
    % Each method of ORO-SPEC §6 is listed by listSimpleMethods if and
    % only if the dispatcher knows it: probed with 7 parameters (no
    % method has 7), a listed one is an arity error, an unlisted one
    % "not implemented".
    test_set_call(listSimpleMethods, [], Signatures),
    maplist(srv_signature_name, Signatures, Listed),
    findall(Name, srv_spec_method(Name), Names),
    length(Params, 7),
    maplist(=(x), Params),
    test_connected(Conn,
                   foldl(srv_listing_probe(Conn, Params, Listed), Names,
                         Bad, [])).
test(listed_methods_are_dispatched, true(Bad == [])) :-
    % Every listed method exists for the dispatcher: with 7 parameters
    % (no method has 7) it is an arity error, never "not implemented".
    % (Not help: a help line is answered at once, ORO-SPEC §1.2.)
    test_set_call(listSimpleMethods, [], Signatures),
    maplist(srv_signature_name, Signatures, Names0),
    sort(Names0, Names1),
    subtract(Names1, ["help"], Names),
    length(Params, 7),
    maplist(=(x), Params),
    test_connected(Conn,
                   foldl(srv_arity_probe(Conn, Params), Names, Bad, [])).
test(methods_alias, true(Methods == Simple)) :-
    test_set_call(listSimpleMethods, [], Simple),
    test_set_call(methods, [], Methods).
test(list_methods_keys, true(Keys == Simple)) :-
    test_set_call(listSimpleMethods, [], Simple),
    test_call(listMethods, [], Reply),
    srv_keys(Reply, Keys).
test(list_methods_descriptions, true(Bad == [])) :-
    srv_map_call(listMethods, [], Pairs),
    exclude(srv_description, Pairs, Bad).
test(unknown_method,
     true(Reply == error("NotImplementedException",
                         "Method \"foo\" not implemented."))) :-
    test_call(foo, [], Reply).
test(method_with_trailing_space,
     true(Reply == error("NotImplementedException",
                         "Method \"add \" not implemented."))) :-
    test_call('add ', ['[a b c]'], Reply).
test(wrong_arity,
     true(Reply == error("NotImplementedException",
                         "Error while executing the request: wrong number of \c
                          parameters provided for method \"add\" (0 were \c
                          provided)."))) :-
    test_call(add, [], Reply).
test(embedded_empty_line_is_a_parameter,
     true(Reply == ok("[]"))) :-
    % three parameters: find(x, [], [?x rdf:type Animal]) -- an empty
    % pattern set answers [] whatever the filters (ORO-SPEC §6.3)
    test_connected(Conn,
                   ( oro_send_raw(Conn, "find\nx\n\n[?x rdf:type Animal]\n#end#\n"),
                     oro_receive(Conn, Reply)
                   )).
test(not_a_set,
     true(Reply == error("NotImplementedException",
                         "Error while executing the request: no method \c
                          prototype for 'add' match the given arguments."))) :-
    test_call(add, ['gorilla likes apple'], Reply).
test(null_set, true(Replies == [ok("true"), ok("true"), ok("[]")])) :-
    % ORO-SPEC §2.2: null (any case) is the empty set.
    test_calls([ check-[null],
                 check-['NULL'],
                 find-[x, 'Null']
               ],
               Replies).
test(braces_are_not_a_set,
     true(Reply == error("NotImplementedException",
                         "Error while executing the request: no method \c
                          prototype for 'add' match the given arguments."))) :-
    test_call(add, ['{a b c}'], Reply).
test(set_not_trimmed,
     true(Replies == [Prototype, Prototype])) :-
    Prototype = error("NotImplementedException",
                      "Error while executing the request: no method \c
                       prototype for 'check' match the given arguments."),
    test_calls([ check-[' [gorilla rdf:type Monkey]'],
                 check-['[gorilla rdf:type Monkey] ']
               ],
               Replies).
test(string_quoting, true(Replies == [Label, Label, Label, Label])) :-
    % ORO-SPEC §2.1: trimmed, one pair of outer quotes removed.
    Label = ok("\"baboon monkey\""),
    test_calls([ getLabel-[baboon],
                 getLabel-['"baboon"'],
                 getLabel-['\'baboon\''],
                 getLabel-['  baboon  ']
               ],
               Replies).
test(bad_unicode_escape,
     true(Name-Start == "laas.openrobots.ontology.exceptions.OntologyServerException"-
                        "Unable to parse unicode value")) :-
    test_call(getLabel, ['\\uZZ'], error(Name, Message)),
    sub_string(Message, 0, 29, _, Start).
test(trailing_empty_lines_dropped,
     true(Messages == [ok("true"), error("NotImplementedException", Arity)])) :-
    % ORO-SPEC §1.2: trailing empty lines are not parameters.
    Arity = "Error while executing the request: wrong number of parameters \c
             provided for method \"check\" (0 were provided).",
    test_connected(Conn,
                   ( oro_send_raw(Conn, "check\n[gorilla rdf:type Monkey]\n\n\n#end#\n\c
                                         check\n\n#end#\n"),
                     test_receive_n(Conn, 2, Messages)
                   )).
test(case_insensitive, [setup(srv_fresh), true(Replies == [ok(""), ok("true")])]) :-
    test_calls([ 'ADD'-['[toto likes tata]'],
                 'cHeCk'-['[toto likes tata]']
               ],
               Replies).
test(two_tokens,
     true(Reply == error("laas.openrobots.ontology.exceptions.IllegalStatementException",
                         "Three tokens are expected in a statement, 2 found \c
                          in toto titi."))) :-
    test_call(add, ['[toto titi]'], Reply).
test(close, true(Messages == [closing, end_of_file])) :-
    test_connected(Conn,
                   ( oro_send(Conn, close, []),
                     test_receive_n(Conn, 2, Messages)
                   )).
test(close_ignores_parameters, true(Messages == [closing, end_of_file])) :-
    test_connected(Conn,
                   ( oro_send(Conn, 'CLOSE', [a, '[b]']),
                     test_receive_n(Conn, 2, Messages)
                   )).
test(help_multiline, true(Kinds == [true, true, true, true])) :-
    test_call(help, [], ok(Text)),
    maplist(srv_contains(Text),
            ["\n", "add(Set)", "find(String, Set)", "listSimpleMethods()"],
            Kinds).
test(help_quoted, true(Quotes == "\"\"")) :-
    test_call(help, [], ok(Text)),
    sub_string(Text, 0, 1, _, First),
    sub_string(Text, _, 1, 0, Last),
    string_concat(First, Last, Quotes).
test(help_end_answered_once, true(Replies == [help, Hello])) :-
    % pyoro's help() sends help\n#end#\n: one answer, then in sync.
    Hello = ok("\"oro-server 0.8.2\""),
    test_connected(Conn,
                   ( oro_send_raw(Conn, "help\n#end#\n"),
                     oro_receive(Conn, Help),
                     oro_call(Conn, hello, [], Reply2)
                   )),
    srv_help_reply(Help, Reply1),
    Replies = [Reply1, Reply2].
test(help_without_end, true(Replies == [help, Hello])) :-
    % A bare help line is answered at once (ORO-SPEC §1.2).
    Hello = ok("\"oro-server 0.8.2\""),
    test_connected(Conn,
                   ( oro_send_raw(Conn, "help\n"),
                     oro_receive(Conn, Help),
                     oro_call(Conn, hello, [], Reply2)
                   )),
    srv_help_reply(Help, Reply1),
    Replies = [Reply1, Reply2].
test(pipelined, [ setup(srv_fresh),
                  true(Messages == [ ok("\"oro-server 0.8.2\""),
                                     ok(""),
                                     ok("true"),
                                     ok("false")
                                   ])
                ]) :-
    test_connected(Conn,
                   ( oro_send_raw(Conn, "hello\n#end#\nADD\n[pa pb pc]\n#end#\n\c
                                         check\n[pa pb pc]\n#end#\n\c
                                         check\n[pc pb pa]\n#end#\n"),
                     test_receive_n(Conn, 4, Messages)
                   )).
test(pipelined_without_newlines, true(Messages == [Hello, Hello, Hello])) :-
    Hello = ok("\"oro-server 0.8.2\""),
    test_connected(Conn,
                   ( oro_send_raw(Conn, "hello\n#end#hello\n#end#\n\nhello\n#end#"),
                     test_receive_n(Conn, 3, Messages)
                   )).
test(crlf, true(Messages == [ok("true"), ok("false")])) :-
    test_connected(Conn,
                   ( oro_send_raw(Conn, "check\r\n[gorilla rdf:type Monkey]\r\n#end#\r\n\c
                                         check\r[gorilla rdf:type Plant]\r#end#\r\n"),
                     test_receive_n(Conn, 2, Messages)
                   )).
test(end_on_parameter_line, true(Messages == [ok("true"), ok("false")])) :-
    test_connected(Conn,
                   ( oro_send_raw(Conn, "check\n[gorilla rdf:type Monkey]#end#\n\c
                                         check\n[gorilla rdf:type Plant]#end#"),
                     test_receive_n(Conn, 2, Messages)
                   )).
test(bare_end,
     true(Messages == [ error("NotImplementedException",
                              "Method \"\" not implemented."),
                        ok("\"oro-server 0.8.2\"")
                      ])) :-
    test_connected(Conn,
                   ( oro_send_raw(Conn, "#end#\nhello\n#end#\n"),
                     test_receive_n(Conn, 2, Messages)
                   )).
test(request_parser_vector, true(Checks == [true, true, true, true, true])) :-
    % ORO-SPEC §13.1, socketConnectorRequestParser: three writes that
    % must give help, addForAgent(TOTO, [...]), test2, help,
    % test3(param1).
    test_call(help, [], Help),
    test_connected(Conn,
                   ( oro_send_raw(Conn, "help\naddForAgent\nTOTO\n\c
                                         [\"TATA likes TOTO\"]\n#end#\ntest2\n"),
                     test_receive_n(Conn, 2, [M1, M2]),
                     oro_send_raw(Conn, "#end#\nhelp\ntest3\nparam1\n#end"),
                     oro_send_raw(Conn, "#\n"),
                     test_receive_n(Conn, 3, [M3, M4, M5])
                   )),
    Checks = [C1, C2, C3, C4, C5],
    srv_same(M1, Help, C1),
    (   (   M2 == error("NotImplementedException",
                        "Method \"addForAgent\" not implemented.")
        ;   M2 = ok(_)
        ;   M2 = error(Name, _),
            Name \== "NotImplementedException"
        )
    ->  C2 = true
    ;   C2 = M2
    ),
    srv_same(M3, error("NotImplementedException",
                       "Method \"test2\" not implemented."), C3),
    srv_same(M4, Help, C4),
    srv_same(M5, error("NotImplementedException",
                       "Method \"test3\" not implemented."), C5).

:- end_tests(srv_dispatch).

%   srv_signature(+Text) is semidet: Text is `name(Type, ...)` as
%   listSimpleMethods must spell it.

srv_signature(Text) :-
    string(Text),
    split_string(Text, "(", "", [Name, Rest]),
    string_codes(Name, [First|Codes]),
    code_type(First, lower),
    forall(member(C, Codes), code_type(C, alnum)),
    string_concat(Args, ")", Rest),
    (   Args == ""
    ->  true
    ;   atomic_list_concat(Types, ', ', Args),
        forall(member(Type, Types),
               memberchk(Type, ['String', 'Set', 'List']))
    ).

srv_signature_name(Text, Name) :-
    split_string(Text, "(", "", [Name|_]).

srv_arity_probe(Conn, Params, Name, Bad0, Bad) :-
    oro_call(Conn, Name, Params, Reply),
    format(string(Expected),
           "Error while executing the request: wrong number of parameters \c
            provided for method \"~w\" (7 were provided).", [Name]),
    (   Reply == error("NotImplementedException", Expected)
    ->  Bad0 = Bad
    ;   Bad0 = [Name-Reply|Bad]
    ).

%   srv_help_reply(+Reply, -Kind): Kind is `help` if Reply is the help
%   text, else Reply.

srv_help_reply(Reply, Kind) :-
    (   Reply = ok(Text),
        sub_string(Text, _, _, _, "add(Set)")
    ->  Kind = help
    ;   Kind = Reply
    ).

%   srv_uuid(+Text) is semidet: Text is a lowercase UUID.

srv_uuid(Text) :-
    string_codes(Text, Codes),
    length(Codes, 36),
    forall(nth1(I, Codes, C),
           (   memberchk(I, [9, 14, 19, 24])
           ->  C == 0'-
           ;   code_type(C, xdigit(_)),
               \+ code_type(C, upper)
           )).

%   srv_spec_method(?Name): the methods of ORO-SPEC §6 (help aside: a
%   help line is answered at once, whatever follows).

srv_spec_method(Name) :-
    member(Name,
           [ "reset", "clear", "hello", "stats", "listMethods",
             "listSimpleMethods", "methods", "makeHtmlDoc", "save", "list",
             "add", "safeAdd", "update", "remove", "retract", "check",
             "checkConsistency", "lookup", "getLabel", "query", "find",
             "getInfos", "about", "getResourceDetails", "getSuperclassesOf",
             "getDirectSuperclassesOf", "getSubclassesOf",
             "getDirectSubclassesOf", "getInstancesOf",
             "getDirectInstancesOf", "getClassesOf", "getDirectClassesOf",
             "getDifferences", "getSimilarities", "discriminate",
             "registerEvent", "clearEvents", "clearEvent",
             "registerEventForAgent", "clearEventsForAgent", "listAgents",
             "checkConsistencyForAgent", "addForAgent", "safeAddForAgent",
             "removeForAgent", "clearForAgent", "updateForAgent",
             "findForAgent", "lookupForAgent", "discriminateForAgent",
             "getInfosForAgent", "revise", "processNL"
           ]).

srv_listing_probe(Conn, Params, Listed, Name, Bad0, Bad) :-
    oro_call(Conn, Name, Params, Reply),
    format(string(Arity),
           "Error while executing the request: wrong number of parameters \c
            provided for method \"~w\" (7 were provided).", [Name]),
    format(string(Unknown), "Method \"~w\" not implemented.", [Name]),
    (   memberchk(Name, Listed)
    ->  Expected = error("NotImplementedException", Arity)
    ;   Expected = error("NotImplementedException", Unknown)
    ),
    (   Reply == Expected
    ->  Bad0 = Bad
    ;   Bad0 = [Name-Reply|Bad]
    ).

srv_same(Got, Expected, Check) :-
    (   Got == Expected
    ->  Check = true
    ;   Check = got(Got)
    ).


                 /*******************************
                 *             CHECK            *
                 *******************************/

:- begin_tests(srv_check,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

srv_check_vector('[gorilla rdf:type Monkey]', "true").
srv_check_vector('[gorilla rdf:type Animal]', "true").
srv_check_vector('[apple rdf:type Plant]', "true").
srv_check_vector('[gorilla rdf:type Plant]', "false").
srv_check_vector('[superman isA coward]', "false").
srv_check_vector('[gorilla rdf:type Monkey, gorilla rdf:type Plant]', "false").
srv_check_vector('[?x eats grass]', "true").
srv_check_vector('[?x eats superman]', "false").
srv_check_vector('[]', "true").
srv_check_vector('["gorilla rdf:type Monkey", \'baboon age 35\']', "true").

test(check, [ forall(srv_check_vector(Set, Expected)),
              true(Reply == ok(Expected))
            ]) :-
    test_call(check, [Set], Reply).

:- end_tests(srv_check).


                 /*******************************
                 *              FIND            *
                 *******************************/

:- begin_tests(srv_find,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

test(no_patterns, true(Reply == ok("[]"))) :-
    test_call(find, ['?mysterious', '[]'], Reply).
test(empty_variable,
     true(Reply == error("laas.openrobots.ontology.exceptions.OntologyServerException",
                         "Calling the find() method with an empty variable."))) :-
    test_call(find, ['', '[?x rdf:type Animal]'], Reply).
test(monkeys, true(Xs == ["baboon", "gorilla"])) :-
    test_set_call(find, [mysterious, '[?mysterious rdf:type oro:Monkey, \c
                                       ?mysterious oro:weight ?value]'], Xs).
test(question_mark_optional, true(Xs == ["baboon", "gorilla"])) :-
    test_set_call(find, ['?m', '[?m rdf:type Monkey]'], Xs).
test(labels, true(Xs == ["baboon monkey", "babouin"])) :-
    test_set_call(find, [label, '[?mysterious rdf:type oro:Monkey, \c
                                  ?mysterious oro:weight ?value, \c
                                  baboon rdfs:label ?label]'], Xs).
test(no_solution, true(Reply == ok("[]"))) :-
    test_call(find, ['?mysterious', '[?mysterious oro:eats oro:banana_tree, \c
                                      ?mysterious oro:isFemale true^^xsd:boolean]'],
              Reply).
test(unknown_variable, true(Reply == ok("[]"))) :-
    test_call(find, [nowhere, '[?x rdf:type Monkey]'], Reply).
test(typed_boolean, [setup(srv_fresh), true(Xs == ["baboon", "fish"])]) :-
    test_ok(add, ['[oro:fish oro:isFemale "true"^^xsd:boolean]']),
    test_set_call(find, [i, '[?i rdf:type owl:Thing, ?i oro:isFemale true]'], Xs).
test(domain_inference, [ setup(srv_fresh),
                         true(Xs == ["baboon", "cow", "gorilla", "sheep"])
                       ]) :-
    test_ok(add, ['[sheep eats grass]']),
    test_set_call(find, [animals, '[?animals rdf:type Animal]'], Xs).
test(literal_values, true(Xs == ["12", "35"])) :-
    test_set_call(find, [a, '[?x rdf:type Monkey, ?x age ?a]'], Xs).
test(numbers_canonical, [ setup(srv_fresh),
                          true(Xs == [["7"], ["150.0"]])
                        ]) :-
    % rdf_db keeps one term for `"+7"^^xsd:int` and `7`: the reply must
    % not depend on which came first.
    test_ok(add, ['[x1 v "+7"^^xsd:int, x2 v "150"^^xsd:double]']),
    test_ok(add, ['[y1 v 7, y2 v 150.0]']),
    test_set_call(find, [o, '[y1 v ?o]'], X1),
    test_set_call(find, [o, '[y2 v ?o]'], X2),
    Xs = [X1, X2].
test(distinct_texts,                 % ORO answers a set of strings
     [ setup(srv_fresh),
       true(Replies == [ ok("[\"robot\"]"), ok("[\"12\"]"),
                         ok("[\"robot\"]"), ok("[\"12\"]") ])
     ]) :-
    test_ok(add, ['[o3 rdfs:label "robot"@en, o3 rdfs:label "robot"@fr, \c
                    o1 hasId 12, o2 hasId "12"]']),
    test_call(find, [l, '[o3 rdfs:label ?l]'], R1),
    test_call(findForAgent, [myself, v, '[?x hasId ?v]'], R2),
    test_call(findForAgent, [myself, l, '[o3 rdfs:label ?l]', '[true]'], R3),
    test_call(find, ['[?v]', '[?x hasId ?v]', '[true]', '[]'], R4),
    Replies = [R1, R2, R3, R4].

:- end_tests(srv_find).


                 /*******************************
                 *         ADD AND CLEAR        *
                 *******************************/

:- begin_tests(srv_counts,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

test(six_animals, [ setup(srv_fresh),
                    true(Xs == ["baboon", "cow", "fish", "gorilla", "horse",
                                "sparrow"])
                  ]) :-
    test_ok(add, ['[oro:horse rdf:type oro:Animal]']),
    test_ok(add, ['[fish rdf:type Animal, sparrow rdf:type Bird, \c
                   Bird rdfs:subClassOf Animal]']),
    test_set_call(find, [instances, '[?instances rdf:type oro:Animal]'], Xs).
test(clear_add_clear, [ setup(srv_fresh),
                        true(Counts-Food == [5, 4, 5, 4]-[["butter", "seeds"], []])
                      ]) :-
    Animals = [instances, '[?instances rdf:type oro:Animal]'],
    test_ok(add, ['[fish rdf:type Animal, sparrow rdf:type Bird, \c
                   Bird rdfs:subClassOf Animal]']),
    test_set_call(find, Animals, A1),
    test_ok(clear, ['[Bird rdfs:subClassOf Animal]']),
    test_set_call(find, Animals, A2),
    test_ok(add, ['[sparrow eats seeds, sparrow eats butter]']),
    test_set_call(find, Animals, A3),
    test_set_call(find, [food, '[oro:sparrow oro:eats ?food]'], F1),
    test_ok(clear, ['[sparrow eats ?food]']),
    test_set_call(find, [food, '[oro:sparrow oro:eats ?food]'], F2),
    test_set_call(find, Animals, A4),
    maplist(length, [A1, A2, A3, A4], Counts),
    Food = [F1, F2].
test(clear_restores, [ setup(srv_fresh),
                       true(After-During == Before-true)
                     ]) :-
    Set = '[gorilla rdfs:label \'KingKong\', gorilla rdfs:comment "KingKong is nice"]',
    test_set_call(getInfos, [gorilla], Before),
    test_ok(add, [Set]),
    test_set_call(getInfos, [gorilla], Added),
    (   memberchk("gorilla label KingKong", Added),
        memberchk("gorilla comment KingKong is nice", Added)
    ->  During = true
    ;   During = Added
    ),
    test_ok(clear, [Set]),
    test_set_call(getInfos, [gorilla], After).
test(clear_wildcard, [ setup(srv_fresh),
                       true(Replies == [ok(""), ok(""), ok("false"), ok("false"),
                                        ok("false"), ok("true")])
                     ]) :-
    % `S ?a ?b` removes everything asserted about S, the ontology's
    % facts included (ORO-SPEC §6.1).
    test_calls([ add-['[kong rdf:type Monkey, kong age 3]'],
                 clear-['[kong ?a ?b, gorilla ?a ?b]'],
                 check-['[kong rdf:type Monkey]'],
                 check-['[kong age 3]'],
                 check-['[gorilla rdf:type Monkey]'],
                 check-['[baboon rdf:type Monkey]']
               ],
               Replies).
test(add_twice_is_idempotent, [ setup(srv_fresh),
                                true(Second == First)
                              ]) :-
    test_ok(add, ['[horse rdf:type Animal, horse age 7]']),
    test_set_call(getInfos, [horse], First),
    test_ok(add, ['[horse rdf:type Animal, horse age 7]']),
    test_set_call(getInfos, [horse], Second).
test(remove, [ setup(srv_fresh),
               true(Replies == [ok(""), ok("true"), ok(""), ok("false")])
             ]) :-
    test_calls([ add-['[horse rdf:type Animal]'],
                 check-['[horse rdf:type Animal]'],
                 remove-['[horse rdf:type Animal]'],
                 check-['[horse rdf:type Animal]']
               ],
               Replies).

:- end_tests(srv_counts).


                 /*******************************
                 *            LOOKUP            *
                 *******************************/

:- begin_tests(srv_lookup,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

srv_lookup_setup :-
    srv_fresh,
    test_ok(add, ['[gorilla rdfs:label "king kong", iddebile rdf:type Human]']).

srv_lookup_vector('princess Daisy', "[]").
srv_lookup_vector('BabouIn', "[[\"baboon\",\"INSTANCE\"]]").
srv_lookup_vector('Baboon monkey', "[[\"baboon\",\"INSTANCE\"]]").
srv_lookup_vector('king kong', "[[\"gorilla\",\"INSTANCE\"]]").
srv_lookup_vector(iddebile, "[[\"iddebile\",\"INSTANCE\"]]").
srv_lookup_vector('Monkey', "[[\"Monkey\",\"CLASS\"]]").

test(lookup, [ setup(srv_lookup_setup),
               forall(srv_lookup_vector(Text, Expected)),
               true(Reply == ok(Expected))
             ]) :-
    test_call(lookup, [Text], Reply).
test(two_hits, [ setup(srv_lookup_setup),
                 true(Pairs == [["KingKong", "CLASS"], ["gorilla", "INSTANCE"]])
               ]) :-
    test_ok(add, ['[KingKong rdfs:subClassOf Monkey, KingKong rdfs:label "king kong"]']),
    test_set_call(lookup, ['king kong'], Pairs).
test(cleared, [ setup(srv_lookup_setup),
                true(Reply == ok("[]"))
              ]) :-
    Set = '[KingKong rdfs:subClassOf Monkey, KingKong rdfs:label "king kong"]',
    test_ok(add, [Set]),
    test_ok(clear, [Set]),
    test_ok(clear, ['[gorilla ?a ?b]']),
    test_call(lookup, ['king kong'], Reply).

srv_kind_setup :-
    srv_fresh,
    test_ok(add, ['[rintintin rdf:type Dog, lassie rdf:type Cat, \c
                   rintintin sees lassie, rintintin hasAge 134]']).

srv_kind_vector(rintintin, instance, "[\"rintintin\"]").
srv_kind_vector(rintintin, class, "[]").
srv_kind_vector(dog, class, "[\"Dog\"]").
srv_kind_vector(dog, instance, "[]").
srv_kind_vector(sees, object_property, "[\"sees\"]").
srv_kind_vector(sees, datatype_property, "[]").
srv_kind_vector(hasage, datatype_property, "[\"hasAge\"]").
srv_kind_vector(dog, 'CLASS', "[\"Dog\"]").
srv_kind_vector(dog, nonsense, "[]").

test(lookup_kind, [ setup(srv_kind_setup),
                    forall(srv_kind_vector(Text, Kind, Expected)),
                    true(Reply == ok(Expected))
                  ]) :-
    test_call(lookup, [Text, Kind], Reply).

:- end_tests(srv_lookup).


                 /*******************************
                 *           TAXONOMY           *
                 *******************************/

:- begin_tests(srv_taxonomy,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

srv_insects :-
    srv_fresh,
    test_ok(add, ['[Insect rdfs:subClassOf Animal, Ladybird rdfs:subClassOf Insect]']).

test(subclasses, [ setup(srv_insects),
                   true(Pairs == [ "Insect"-"Insect", "Ladybird"-"Ladybird",
                                   "Monkey"-"Monkey", "MyAnimals"-"MyAnimals"
                                 ])
                 ]) :-
    srv_map_call(getSubclassesOf, ['Animal'], Pairs).
test(direct_subclasses, [ setup(srv_insects),
                          true(Keys == ["Insect", "Monkey", "MyAnimals"])
                        ]) :-
    test_call(getDirectSubclassesOf, ['Animal'], Reply),
    srv_keys(Reply, Keys).
test(superclasses, [ setup(srv_insects),
                     true(Keys == ["Animal", "Insect", "owl:Thing"])
                   ]) :-
    % rdfs:Resource may or may not be there (ORO-SPEC §6.4).
    test_call(getSuperclassesOf, ['Ladybird'], Reply),
    srv_keys(Reply, Keys0),
    subtract(Keys0, ["rdfs:Resource"], Keys).
test(direct_superclasses, [ setup(srv_insects),
                            true(Reply == ok("{\"Insect\":\"Insect\"}"))
                          ]) :-
    test_call(getDirectSuperclassesOf, ['Ladybird'], Reply).
test(instances, [ setup(srv_insects),
                  true(Pairs == [ "baboon"-"baboon monkey", "cow"-"cow",
                                  "gorilla"-"gorilla"
                                ])
                ]) :-
    srv_map_call(getInstancesOf, ['Animal'], Pairs).
test(direct_instances, [ setup(srv_insects),
                         true(Keys == ["apple", "banana_tree", "grass"])
                       ]) :-
    test_call(getDirectInstancesOf, ['Plant'], Reply),
    srv_keys(Reply, Keys).
test(direct_classes, [ setup(srv_insects),
                       true(Pairs == ["Monkey"-"Monkey", "MyAnimals"-"MyAnimals"])
                     ]) :-
    srv_map_call(getDirectClassesOf, [baboon], Pairs).
test(classes, [ setup(srv_insects),
                true(Missing == [])
              ]) :-
    test_call(getClassesOf, [baboon], Reply),
    srv_keys(Reply, Keys),
    subtract(["Animal", "Monkey", "MyAnimals"], Keys, Missing).
test(lattice, [ setup(srv_insects),
                true(Keys == ["B", "C", "D", "E", "F", "I", "J", "K"])
              ]) :-
    test_call(getSubclassesOf, ['A'], Reply),
    srv_keys(Reply, Keys).
test(not_a_class,
     true(Reply == error("com.hp.hpl.jena.shared.NotFoundException",
                         "The class baboon does not exists in the ontology \c
                          (tip: if this resource is not in the default \c
                          namespace, be sure to add the namespace prefix!)"))) :-
    test_call(getDirectSuperclassesOf, [baboon], Reply).
test(not_an_individual,
     true(Reply == error("com.hp.hpl.jena.shared.NotFoundException",
                         "Monkey is not an individual!"))) :-
    test_call(getClassesOf, ['Monkey'], Reply).
test(classes_of_owl_class, true(Reply == ok("{}"))) :-
    test_call(getClassesOf, ['owl:Class'], Reply).
test(instances_of_individual, true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    test_call(getInstancesOf, [baboon], error(Name, _)).

:- end_tests(srv_taxonomy).

%   The bundled ontology never names owl:Thing, the top of every answer.

:- begin_tests(srv_taxonomy_commonsense,
               [ setup(srv_start_commonsense),
                 cleanup(srv_stop)
               ]).

test(superclasses, true(Pairs == [ "Agent"-"agent",
                                   "EmbodiedAgent"-"embodied agent",
                                   "owl:Thing"-"Thing"
                                 ])) :-
    srv_map_call(getSuperclassesOf, ['Robot'], Pairs).
test(classes_of, true(Keys == ["Agent", "EmbodiedAgent", "Robot", "owl:Thing"])) :-
    test_call(getClassesOf, [myself], Reply),
    srv_keys(Reply, Keys).
test(label_of_thing, true(Reply == ok("\"Thing\""))) :-
    test_call(getLabel, ['owl:Thing'], Reply).
test(ontology_header_no_instance, true(Keys == [])) :-
    test_call(getInstancesOf, ['owl:Thing'], Reply),
    srv_keys(Reply, Keys0),
    include(==("http://kb.openrobots.org"), Keys0, Keys).

:- end_tests(srv_taxonomy_commonsense).


                 /*******************************
                 *   INFOS, LABELS, DETAILS     *
                 *******************************/

:- begin_tests(srv_infos,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

test(get_infos, true(Missing == [])) :-
    test_set_call(getInfos, [baboon], Infos),
    subtract([ "baboon type Animal", "baboon isFemale true",
               "baboon type Monkey", "baboon climbsOn banana_tree",
               "baboon age 35"
             ], Infos, Missing).
test(get_infos_subject_only, true(Others == [])) :-
    test_set_call(getInfos, [baboon], Infos),
    exclude(srv_about_baboon, Infos, Others).
test(get_infos_prefixed, true(Prefixed == Plain)) :-
    test_set_call(getInfos, [baboon], Plain),
    test_set_call(getInfos, ['oro:baboon'], Prefixed).
test(get_infos_distinct_texts,      % labels in two languages, one text
     [ setup(srv_fresh),
       true(Reply == ok("[\"o3 label robot\"]"))
     ]) :-
    test_ok(add, ['[o3 rdfs:label "robot"@en, o3 rdfs:label "robot"@fr]']),
    test_call(getInfos, [o3], Reply).
test(about_alias, true(About == Infos)) :-
    test_set_call(getInfos, [baboon], Infos),
    test_set_call(about, [baboon], About).
test(get_infos_unknown,
     true(Reply == error("com.hp.hpl.jena.shared.NotFoundException",
                         "The node http://kb.openrobots.org#i_d_ont_exist was \c
                          not found in the ontology (tip: check the \c
                          namespaces!)."))) :-
    test_call(getInfos, [i_d_ont_exist], Reply).
test(label, true(Reply == ok("\"baboon monkey\""))) :-
    test_call(getLabel, [baboon], Reply).
test(label_is_name, true(Reply == ok("\"gorilla\""))) :-
    test_call(getLabel, [gorilla], Reply).
test(label_unknown, true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    test_call(getLabel, [i_d_ont_exist], error(Name, _)).
test(details_monkey, true(Details == Expected)) :-
    test_call(getResourceDetails, ['Monkey'], Reply),
    srv_details(Reply, Details),
    srv_details(ok("{\"name\":\"Monkey\",\"id\":\"Monkey\",\"type\":\"class\",\c
                    \"sameAs\":[],\"attributes\": [\c
                    {\"name\":\"Parents\",\"id\":\"superClasses\",\"values\":\c
                    [{\"name\":\"Animal\", \"id\":\"Animal\"}]},\c
                    {\"name\":\"Children\",\"id\":\"subClasses\",\"values\":[]},\c
                    {\"name\":\"Instances\",\"id\":\"instances\",\"values\":\c
                    [{\"name\":\"baboon monkey\", \"id\":\"baboon\"},\c
                    {\"name\":\"gorilla\", \"id\":\"gorilla\"}]}]}"),
                Expected).
test(details_layout, true(Start == Prefix)) :-
    % One line, no spaces but the one after "attributes": (oro-view).
    Prefix = "{\"name\":\"Monkey\",\"id\":\"Monkey\",\"type\":\"class\",\c
              \"sameAs\":[],\"attributes\": [{\"name\":\"Parents\",\c
              \"id\":\"superClasses\",\"values\":[{\"name\":\"Animal\", \c
              \"id\":\"Animal\"}]},",
    string_length(Prefix, Length),
    test_call(getResourceDetails, ['Monkey'], ok(Line)),
    sub_string(Line, 0, Length, _, Start).
test(details_instance, true(Type-Classes == "instance"-["Monkey", "MyAnimals"])) :-
    test_call(getResourceDetails, [baboon], Reply),
    srv_details(Reply, Details),
    memberchk("type"-Type, Details),
    memberchk("attributes"-Attributes, Details),
    memberchk(Classes0, Attributes),
    memberchk("id"-"classes", Classes0),
    memberchk("values"-Values, Classes0),
    findall(Id, ( member(V, Values), memberchk("id"-Id, V) ), Classes1),
    msort(Classes1, Classes).
test(details_unknown, true(Name == "com.hp.hpl.jena.shared.NotFoundException")) :-
    test_call(getResourceDetails, [i_d_ont_exist], error(Name, _)).

:- end_tests(srv_infos).

%   The ids of getResourceDetails: the name of a resource of the default
%   namespace, the full IRI of any other, as oro-server 0.8.2 gives them
%   (foaf:Person is http://xmlns.com/foaf/0.1/Person), for the resource
%   described and for those it lists.

srv_start_equivalent :-
    test_fixture('equivalent_properties.ttl', File),
    test_server_start([commonsense(false), ontology(File)]).

:- begin_tests(srv_details_ids,
               [ setup(srv_start_equivalent),
                 cleanup(srv_stop)
               ]).

test(foreign_class, true(Id-Name == "http://xmlns.com/foaf/0.1/Person"-"person")) :-
    test_call(getResourceDetails, ['foaf:Person'], Reply),
    srv_details(Reply, Details),
    memberchk("id"-Id, Details),
    memberchk("name"-Name, Details).
test(foreign_class_listed, true(Classes == ["http://xmlns.com/foaf/0.1/Person"])) :-
    test_call(getResourceDetails, [someone], Reply),
    srv_details(Reply, Details),
    memberchk("attributes"-Attributes, Details),
    memberchk(Classes0, Attributes),
    memberchk("id"-"classes", Classes0),
    memberchk("values"-Values, Classes0),
    findall(Id, ( member(V, Values), memberchk("id"-Id, V) ), Classes).
test(default_namespace, true(Id-Parents == "Shrub"-["Item"])) :-
    test_call(getResourceDetails, ['Shrub'], Reply),
    srv_details(Reply, Details),
    memberchk("id"-Id, Details),
    memberchk("attributes"-[SuperClasses|_], Details),
    memberchk("values"-Values, SuperClasses),
    findall(P, ( member(V, Values), memberchk("id"-P, V) ), Parents).
test(full_iri_given, true(Id == "http://example.org/property/hue")) :-
    test_call(getResourceDetails, ['<http://example.org/property/hue>'], Reply),
    srv_details(Reply, Details),
    memberchk("id"-Id, Details).

:- end_tests(srv_details_ids).

%   srv_details(+Reply, -Details): the JSON of getResourceDetails with
%   the order of `values` and `sameAs` lists ignored.

srv_details(Reply, Details) :-
    test_expect_ok(getResourceDetails, Reply, Line),
    test_json(Line, Details0),
    srv_unordered(Details0, Details).

srv_unordered(Pairs0, Pairs) :-
    is_list(Pairs0),
    Pairs0 = [_-_|_],
    !,
    maplist(srv_unordered_pair, Pairs0, Pairs).
srv_unordered(List0, List) :-
    is_list(List0),
    !,
    maplist(srv_unordered, List0, List).
srv_unordered(Value, Value).

srv_unordered_pair(Key-Value0, Key-Value) :-
    srv_unordered(Value0, Value1),
    (   memberchk(Key, ["values", "sameAs"])
    ->  msort(Value1, Value)
    ;   Value = Value1
    ).


                 /*******************************
                 *        ADMINISTRATION        *
                 *******************************/

srv_start_admin :-
    tmp_file(oro_save, Dir),
    make_directory(Dir),
    assertz(srv_save_dir(Dir)),
    test_fixture('testsuite.ttl', File),
    srv_start([commonsense(false), ontology(File), save_dir(Dir)]).

srv_stop_admin :-
    srv_stop,
    forall(retract(srv_save_dir(Dir)),
           delete_directory_and_contents(Dir)).

:- begin_tests(srv_admin,
               [ setup(srv_start_admin),
                 cleanup(srv_stop_admin)
               ]).

test(reset_forgets, true(Replies == [ok(""), ok("true"), ok(""), ok("false")])) :-
    test_calls([ add-['[horse rdf:type Animal]'],
                 check-['[horse rdf:type Animal]'],
                 reset-[],
                 check-['[horse rdf:type Animal]']
               ],
               Replies).
test(clear_without_parameters_resets,
     true(Replies == [ok(""), ok(""), ok("false"), ok("true")])) :-
    test_calls([ add-['[horse rdf:type Animal]'],
                 clear-[],
                 check-['[horse rdf:type Animal]'],
                 check-['[gorilla rdf:type Monkey]']
               ],
               Replies).
test(reset_keeps_ontology, true(Reply == ok("true"))) :-
    test_ok(clear, ['[gorilla ?a ?b]']),
    test_ok(reset, []),
    test_call(check, ['[gorilla rdf:type Monkey, gorilla age 12]'], Reply).
test(save, [ setup(srv_fresh),
             true(Contains == [true, true])
           ]) :-
    test_ok(add, ['[horse rdf:type Animal]']),
    test_ok(save, ['saved.owl']),
    srv_save_dir(Dir),
    directory_file_path(Dir, 'saved.owl', File),
    read_file_to_string(File, Text, []),
    maplist(srv_contains(Text), ["horse", "gorilla"], Contains).
test(save_snapshot, true(Snapshots = [_])) :-
    test_ok(save, []),
    srv_save_dir(Dir),
    directory_files(Dir, Entries),
    include(srv_snapshot_file, Entries, Snapshots).
test(save_outside,
     true(Reply == error("laas.openrobots.ontology.exceptions.OntologyServerException",
                         "Error while opening ../x.owl to output the ontology: \c
                          files are only written under the save directory."))) :-
    test_call(save, ['../x.owl'], Reply).
test(save_absolute,
     true(Name == "laas.openrobots.ontology.exceptions.OntologyServerException")) :-
    test_call(save, ['/tmp/oro-test-x.owl'], error(Name, _)).
test(save_absolute_inside, true(Exists == true)) :-
    srv_save_dir(Dir0),
    absolute_file_name(Dir0, Dir),
    directory_file_path(Dir, 'inside.owl', File),
    test_ok(save, [File]),
    test_bool(exists_file(File), Exists).

:- end_tests(srv_admin).


                 /*******************************
                 *         SEED SESSION         *
                 *******************************/

:- begin_tests(srv_seed_session,
               [ setup(srv_start_commonsense),
                 cleanup(srv_stop)
               ]).

srv_seed_table :-
    srv_fresh,
    test_ok(add, ['[kitchen_table rdf:type Table, fork1 rdf:type Fork, \c
                   glass1 rdf:type Glass]']),
    test_ok(add, ['[fork1 isOn kitchen_table]']).

test(find_on_table, [ setup(srv_seed_table),
                      true(Reply == ok("[\"fork1\"]"))
                    ]) :-
    test_call(find, [o, '[?o isAt kitchen_table]'], Reply).
test(tableware, [ setup(srv_seed_table),
                  true(Replies == [ok("false"), ok(""), ok("true")])
                ]) :-
    test_calls([ check-['[fork1 rdf:type Artifact]'],
                 add-['[Fork rdfs:subClassOf Tableware,Glass rdfs:subClassOf Tableware]'],
                 check-['[fork1 rdf:type Artifact]']
               ],
               Replies).
test(label_myself, true(Reply == ok("\"myself\""))) :-
    test_call(getLabel, [myself], Reply).
test(glass_on_table, [ setup(srv_seed_table),
                       true(Xs == ["fork1", "glass1"])
                     ]) :-
    test_ok(add, ['[Fork rdfs:subClassOf Tableware,Glass rdfs:subClassOf Tableware]']),
    test_ok(add, ['[glass1 isOn kitchen_table]']),
    test_set_call(find, [o, '[?o isAt kitchen_table, ?o rdf:type Artifact]'], Xs).
test(events, [ setup(srv_fresh),
               true(Messages == [ ok(""), ok(""), ok("[\"fork1\"]"), uuid,
                                  ok(""), event(Id, "[\"fork1\"]"),
                                  ok(""), event(Id, "[\"glass1\"]")
                                ])
             ]) :-
    % The whole seed session: the reply comes before the event it causes.
    test_connected(Conn,
                   ( oro_call(Conn, add, ['[kitchen_table rdf:type Table, \c
                                            fork1 rdf:type Fork, \c
                                            glass1 rdf:type Glass]'], R1),
                     oro_call(Conn, add, ['[fork1 isOn kitchen_table]'], R2),
                     oro_call(Conn, find, [o, '[?o isAt kitchen_table]'], R3),
                     oro_call(Conn, registerEvent,
                              ['NEW_INSTANCE', 'ON_TRUE', o,
                               '[?o isAt kitchen_table, ?o rdf:type Artifact]'],
                              R4),
                     oro_send(Conn, add, ['[Fork rdfs:subClassOf Tableware,\c
                                            Glass rdfs:subClassOf Tableware]']),
                     test_receive_n(Conn, 2, [R5, E1]),
                     oro_send(Conn, add, ['[glass1 isOn kitchen_table]']),
                     test_receive_n(Conn, 2, [R6, E2])
                   )),
    (   R4 = ok(Id),
        srv_uuid(Id)
    ->  U = uuid
    ;   U = R4
    ),
    Messages = [R1, R2, R3, U, R5, E1, R6, E2].

:- end_tests(srv_seed_session).


                 /*******************************
                 *           BAD INPUT          *
                 *******************************/

:- begin_tests(srv_bad_input,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

test(malformed_batch_changes_nothing,
     [ setup(srv_fresh),
       true(Replies == [ ok("false"),
                         error("laas.openrobots.ontology.exceptions.IllegalStatementException",
                               "Three tokens are expected in a statement, 2 \c
                                found in toto titi."),
                         ok("false"),
                         ok("false")
                       ])
     ]) :-
    test_calls([ check-['[horse rdf:type Animal]'],
                 add-['[horse rdf:type Animal, toto titi, fish rdf:type Animal]'],
                 check-['[horse rdf:type Animal]'],
                 check-['[fish rdf:type Animal]']
               ],
               Replies).
test(literal_as_class,
     [ setup(srv_fresh),
       true(Replies == [ error("laas.openrobots.ontology.exceptions.IllegalStatementException",
                               "In Fork rdfs:subClassOf \"x\", the object must be \c
                                a resource (a class, a property or an \c
                                individual), not a literal."),
                         ok("false"),
                         ok("{\"owl:Thing\":\"Thing\"}")
                       ])
     ]) :-
    test_calls([ add-['[horse rdf:type Animal, Fork rdfs:subClassOf "x"]'],
                 check-['[horse rdf:type Animal]'],
                 getDirectSuperclassesOf-['Animal']
               ],
               Replies).
test(half_surrogate_pair,
     [ setup(srv_fresh),
       true(Replies == [Bad1, Bad2, ok("false")])
     ]) :-
    Bad1 = error("laas.openrobots.ontology.exceptions.OntologyServerException",
                 "Unable to parse unicode value: \\ud800"),
    Bad2 = error("laas.openrobots.ontology.exceptions.OntologyServerException",
                 "Unable to parse unicode value:  x label \"\\ud800\""),
    test_calls([ lookup-['\\ud800'],
                 add-['[horse rdf:type Animal, x label "\\ud800"]'],
                 check-['[horse rdf:type Animal]']
               ],
               Replies).
test(unterminated_quote,
     [ setup(srv_fresh),
       true(Replies == [Illegal, Illegal, ok("false"), ok("\"oro-server 0.8.2\"")])
     ]) :-
    Illegal = "laas.openrobots.ontology.exceptions.IllegalStatementException",
    test_connected(Conn,
                   ( oro_call(Conn, add, ['["toto likes tata, horse rdf:type Animal]'], R1),
                     oro_call(Conn, add, ['[\'toto likes tata]'], R2),
                     oro_call(Conn, check, ['[horse rdf:type Animal]'], R3),
                     oro_call(Conn, hello, [], R4)
                   )),
    maplist(test_error_name, [R1, R2], [E1, E2]),
    Replies = [E1, E2, R3, R4].
test(unterminated_quote_three_tokens,
     [ setup(srv_fresh),
       true(Replies-Unchanged ==
            [ error(Illegal, "Not a statement: \"a b \\\"unterminated, c d e\"."),
              error(Illegal, "Not a statement: \"a b \\\"unterminated, c d e\"."),
              ok("[]"),
              ok("false")
            ]-true)
     ]) :-
    % Three tokens are left when the quote swallows the rest of the set.
    Illegal = "laas.openrobots.ontology.exceptions.IllegalStatementException",
    srv_store_state(Before),
    test_calls([ add-['[a b "unterminated, c d e]'],
                 add-['[horse rdf:type Animal, a b "unterminated, c d e]'],
                 find-[o, '[a b ?o]'],
                 check-['[horse rdf:type Animal]']
               ],
               Replies),
    srv_store_state(After),
    test_bool(After == Before, Unchanged).
test(unterminated_quote_in_object,
     [ setup(srv_fresh),
       forall(member(Set, [ '[toto likes tata"]',
                            '[toto likes \'tata tutu]',
                            '[toto likes john\'s]',
                            '[toto likes "tata"tutu]'
                          ])),
       true(Name-Unchanged ==
            "laas.openrobots.ontology.exceptions.IllegalStatementException"-true)
     ]) :-
    srv_store_state(Before),
    test_call(add, [Set], Reply),
    test_error_name(Reply, Name),
    srv_store_state(After),
    test_bool(After == Before, Unchanged).
test(closed_quotes_accepted,
     [ setup(srv_fresh),
       true(Os == ["it's", "say \"hi\""])
     ]) :-
    test_ok(add, ['[toto says \'say "hi"\', toto says "it\'s"]']),
    test_set_call(find, [o, '[toto says ?o]'], Os).
test(pattern_in_add,
     [ setup(srv_fresh),
       true(Replies == [ error(Illegal, "A complete statement is expected \c
                                         here, not a pattern: x ?p y."),
                         error(Illegal, "A complete statement is expected \c
                                         here, not a pattern: x ?p y."),
                         ok("false")
                       ])
     ]) :-
    Illegal = "laas.openrobots.ontology.exceptions.IllegalStatementException",
    test_calls([ add-['[horse rdf:type Animal, x ?p y]'],
                 update-['[horse rdf:type Animal,  x ?p y ]'],
                 check-['[horse rdf:type Animal]']
               ],
               Replies).
test(invalid_utf8,
     true(Messages == [ error("laas.openrobots.ontology.exceptions.OntologyServerException",
                              "The request is not valid UTF-8."),
                        ok("\"oro-server 0.8.2\"")
                      ])) :-
    string_codes("check\n[a ", Before),
    string_codes(" c]\n#end#\n", After),
    append([Before, [0xff, 0xc3, 0x28], After], Bytes),
    test_connected(Conn,
                   ( oro_send_raw(Conn, bytes(Bytes)),
                     oro_receive(Conn, M1),
                     oro_call(Conn, hello, [], M2)
                   )),
    Messages = [M1, M2].
test(overlong_utf8,
     true(Messages == [ error("laas.openrobots.ontology.exceptions.OntologyServerException",
                              "The request is not valid UTF-8."),
                        ok("\"oro-server 0.8.2\"")
                      ])) :-
    % 0xC0 0xAF is an overlong '/'.
    string_codes("getLabel\n", Before),
    string_codes("\n#end#\n", After),
    append([Before, [0xc0, 0xaf], After], Bytes),
    test_connected(Conn,
                   ( oro_send_raw(Conn, bytes(Bytes)),
                     oro_receive(Conn, M1),
                     oro_call(Conn, hello, [], M2)
                   )),
    Messages = [M1, M2].
test(valid_utf8, [ setup(srv_fresh),
                   true(Replies == [ok(""), ok(Quoted)])
                 ]) :-
    Label = "\u00e9t\u00e9 \u00e0 Z\u00fcrich \u2014 \u2615 \U0001F916",
    format(string(Set), '[cafe rdfs:label "~w"]', [Label]),
    format(string(Quoted), '"~w"', [Label]),
    test_calls([ add-[Set],
                 getLabel-[cafe]
               ],
               Replies).
test(nul_bytes, true(Kinds == [answered, ok("\"oro-server 0.8.2\"")])) :-
    test_connected(Conn,
                   ( oro_send_raw(Conn, "check\n[nul\u0000x likes tata]\n#end#\n"),
                     oro_receive(Conn, M1),
                     oro_send_raw(Conn, "hel\u0000lo\n#end#\n"),
                     oro_receive(Conn, M2),
                     oro_call(Conn, hello, [], M3)
                   )),
    (   maplist(srv_reply_kind, [M1, M2], K12),
        subtract(K12, [ok, error], [])
    ->  Kinds = [answered, M3]
    ;   Kinds = [M1, M2, M3]
    ).
test(request_too_large,
     [ setup(srv_fresh),
       true(Result == [ error, end_of_file,
                        ok("\"oro-server 0.8.2\""),
                        ["baboon", "cow", "gorilla"]
                      ])
     ]) :-
    setup_call_cleanup(
        set_setting(oro_server:max_request_size, 1048576),
        srv_too_large(Result),
        restore_setting(oro_server:max_request_size)).
test(disconnect_mid_request, [ setup(srv_fresh),
                               true(Replies == [ok("\"oro-server 0.8.2\""), ok("false")])
                             ]) :-
    test_connected(Conn, oro_send_raw(Conn, "add\n[midway rdf:type Animal")),
    test_connected(Conn2, oro_send_raw(Conn2, "add\n[midway rdf:type Animal]\n#en")),
    test_calls([ hello-[],
                 check-['[midway rdf:type Animal]']
               ],
               Replies).
test(disconnect_before_reply, true(Reply == ok("\"oro-server 0.8.2\""))) :-
    test_connected(Conn, oro_send(Conn, listMethods, [])),
    test_call(hello, [], Reply).

:- end_tests(srv_bad_input).

%   srv_too_large(-Result): send a 2 MB line (the limit is 1 MiB) from
%   a helper thread (the server stops reading it, so the write may
%   block or fail); expect an error then the end of the connection;
%   then a second client must be served and nothing added.  The sender
%   is joined before the connection is closed (closing a stream another
%   thread is writing to would wait for that thread); if it is still
%   blocked after 10 s it is aborted.

srv_too_large([Kind, Closed, Hello, Check]) :-
    length(Codes, 2097152),
    maplist(=(0'a), Codes),
    string_codes(Big, Codes),
    atomics_to_string(["add\n[", Big, " rdf:type Animal]\n#end#\n"], Request),
    message_queue_create(Queue),
    test_connected(Conn,
                   ( thread_create(srv_send_big(Conn, Request, Queue), Sender, []),
                     oro_receive(Conn, Reply),
                     oro_receive(Conn, Closed),
                     (   thread_get_message(Queue, sent(_), [timeout(10)])
                     ->  true
                     ;   catch(thread_signal(Sender, abort), _, true)
                     ),
                     thread_join(Sender, _)
                   )),
    message_queue_destroy(Queue),
    (   Reply = error(_, Message),
        sub_string(Message, _, _, _, "1048576")
    ->  Kind = error
    ;   Kind = Reply
    ),
    test_call(hello, [], Hello),
    test_set_call(find, [x, '[?x rdf:type Animal]'], Check).

srv_send_big(Conn, Request, Queue) :-
    catch(oro_send_raw(Conn, Request), Error, true),
    thread_send_message(Queue, sent(Error)).


                 /*******************************
                 *          CONCURRENCY         *
                 *******************************/

:- begin_tests(srv_concurrency,
               [ setup(srv_start_testsuite),
                 cleanup(srv_stop)
               ]).

test(eight_clients, [ setup(srv_fresh),
                      true(Results-Count == Expected-1600)
                    ]) :-
    numlist(1, 8, Clients),
    findall(N-ok, member(N, Clients), Expected),
    test_server_port(Port),
    message_queue_create(Queue),
    maplist(srv_start_client(Port, Queue), Clients, Threads),
    srv_collect(8, Queue, Results0),
    maplist(srv_join, Threads),
    message_queue_destroy(Queue),
    keysort(Results0, Results),
    test_set_call(find, [s, '[?s ccMember ccSet]'], Members),
    length(Members, Count).

:- end_tests(srv_concurrency).

srv_start_client(Port, Queue, N, Thread) :-
    thread_create(srv_client(Port, Queue, N), Thread, []).

%   srv_client(+Port, +Queue, +N): add cc_N_1 ... cc_N_200 ccMember ccSet
%   in 20 batches of 10 on one connection, then check them all; send
%   N-ok or N-Problem to Queue.

srv_client(Port, Queue, N) :-
    catch(setup_call_cleanup(
              oro_connect(Port, Conn),
              srv_client_work(Conn, N, Result),
              oro_disconnect(Conn)),
          Error,
          Result = exception(Error)),
    thread_send_message(Queue, N-Result).

srv_client_work(Conn, N, Result) :-
    numlist(0, 19, Batches),
    foldl(srv_client_batch(Conn, N), Batches, [], Bad),
    numlist(1, 200, Is),
    maplist(srv_cc_statement(N), Is, All),
    test_set_text(All, AllText),
    oro_call(Conn, check, [AllText], Check, 30),
    (   Bad == [],
        Check == ok("true")
    ->  Result = ok
    ;   Result = failed(Bad, Check)
    ).

srv_client_batch(Conn, N, B, Bad0, Bad) :-
    From is B*10 + 1,
    To is From + 9,
    numlist(From, To, Is),
    maplist(srv_cc_statement(N), Is, Statements),
    test_set_text(Statements, Text),
    oro_call(Conn, add, [Text], Reply, 30),
    (   Reply == ok("")
    ->  Bad = Bad0
    ;   Bad = [B-Reply|Bad0]
    ).

srv_cc_statement(N, I, Statement) :-
    format(string(Statement), "cc_~d_~d ccMember ccSet", [N, I]).

%   srv_collect(+N, +Queue, -Results): N results, 120 s at most in all
%   (a missing one is reported as missing).

srv_collect(N, Queue, Results) :-
    get_time(Now),
    Deadline is Now + 120,
    length(Results, N),
    maplist(srv_collect_one(Queue, Deadline), Results).

srv_collect_one(Queue, Deadline, Result) :-
    (   thread_get_message(Queue, Result0, [deadline(Deadline)])
    ->  Result = Result0
    ;   Result = missing-timeout
    ).

%   srv_join(+Thread): join a client thread; one that did not report in
%   time is aborted first (its socket waits are bounded anyway).

srv_join(Thread) :-
    (   catch(thread_property(Thread, status(running)), _, fail)
    ->  catch(thread_signal(Thread, abort), _, true)
    ;   true
    ),
    thread_join(Thread, _).


                 /*******************************
                 *        SESSION REPLAY        *
                 *******************************/

:- begin_tests(srv_replay,
               [ setup(srv_start([robot_id('JIDOKUKA_ROBOT')])),
                 cleanup(srv_stop)
               ]).

test(robot_session_2011, true(Problems == [])) :-
    test_path('../../shared/workloads/robot-session-2011.log', Log),
    (   exists_file(Log)
    ->  srv_replay(Log, Problems)
    ;   format(user_error,
               "~NNotice: ~w not found: robot session replay skipped.~n",
               [Log]),
        Problems = []
    ).

:- end_tests(srv_replay).

%   srv_replay(+Log, -Problems)
%
%   Replay every request of Log, one connection per `[thread N]`, in log
%   order, and print a one-line summary on user_error.  Problems lists
%   the lines that could not be parsed, the requests that got no ok or
%   error answer, and the requests to listed methods (same name and
%   number of parameters, case-insensitive) that answered
%   NotImplementedException.

srv_replay(Log, Problems) :-
    read_file_to_string(Log, Text, [encoding(utf8)]),
    split_string(Text, "\n", "\r", Lines),
    convlist(test_log_request, Lines, Requests0),
    partition(srv_unparsed, Requests0, Unparsed, Requests),
    test_set_call(listSimpleMethods, [], Signatures),
    maplist(srv_signature_key, Signatures, Keys),
    sort(Keys, Listed),
    test_server_port(Port),
    call_cleanup(
        ( maplist(srv_replay_request(Port, Listed), Requests, Outcomes),
          aggregate_all(count, srv_replay_conn(_, _), NConns)
        ),
        forall(retract(srv_replay_conn(_, Conn)),
               oro_disconnect(Conn))),
    srv_replay_summary(Outcomes, NConns),
    include(srv_replay_problem, Outcomes, Bad),
    append(Unparsed, Bad, Problems).

srv_replay_summary(Outcomes, NConns) :-
    length(Outcomes, Count),
    aggregate_all(count, member(ok(_), Outcomes), NOk),
    aggregate_all(count, member(error(_, _), Outcomes), NError),
    findall(M/A, member(not_implemented(M/A), Outcomes), NotImpl),
    length(NotImpl, NNotImpl),
    sort(NotImpl, NotImplMethods),
    (   NotImplMethods == []
    ->  NotImplText = none
    ;   maplist(srv_method_text, NotImplMethods, Texts),
        atomic_list_concat(Texts, ', ', NotImplText)
    ),
    include(srv_replay_problem, Outcomes, Bad),
    length(Bad, NBad),
    format(user_error,
           "~Nreplay: ~d requests on ~d connections: ~d ok, ~d errors, ~d \c
            NotImplementedException for methods not implemented yet \c
            (~w), ~d problems~n",
           [Count, NConns, NOk, NError, NNotImpl, NotImplText, NBad]).

srv_replay_problem(problem(_, _)).

srv_method_text(Method/Arity, Text) :-
    format(string(Text), "~w/~d", [Method, Arity]).

%   srv_signature_key(+Signature, -Key): Key is LowerName/Arity.

srv_signature_key(Signature, Lower/Arity) :-
    split_string(Signature, "(", "", [Name, Rest]),
    string_lower(Name, Lower),
    (   Rest == ")"
    ->  Arity = 0
    ;   split_string(Rest, ",", "", Parts),
        length(Parts, Arity)
    ).

%   srv_replay_request(+Port, +Listed, +Request, -Outcome)
%
%   Outcome is ok(Method), error(Method, Name),
%   not_implemented(Method/Arity) (a method not listed by
%   listSimpleMethods) or problem(Method, Reply).

srv_replay_request(Port, Listed, request(_, Thread, Method, Params),
                   Outcome) :-
    (   srv_replay_conn(Thread, Conn)
    ->  true
    ;   oro_connect(Port, Conn),
        assertz(srv_replay_conn(Thread, Conn))
    ),
    oro_call(Conn, Method, Params, Reply, 30),
    string_lower(Method, Lower),
    length(Params, Arity),
    (   Reply = error("NotImplementedException", _)
    ->  (   memberchk(Lower/Arity, Listed)
        ->  Outcome = problem(Method, Reply)
        ;   Outcome = not_implemented(Method/Arity)
        )
    ;   Reply = ok(_)
    ->  Outcome = ok(Method)
    ;   Reply = error(Name, _)
    ->  Outcome = error(Method, Name)
    ;   Outcome = problem(Method, Reply)
    ).
