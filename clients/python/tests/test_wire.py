"""The encoding of requests and the decoding of value lines (no server)."""

import unittest

import support  # noqa: F401  (puts pyoro on the path)
from pyoro.wire import IdList, decode_lines, decode_value, encode_request


class DecodeTest(unittest.TestCase):

    def test_scalars(self):
        self.assertIs(decode_value("true"), True)
        self.assertIs(decode_value("false"), False)
        self.assertIsNone(decode_value("null"))
        self.assertEqual(decode_value("42"), 42)
        self.assertIsInstance(decode_value("42"), int)
        self.assertEqual(decode_value("-3.5"), -3.5)
        self.assertEqual(decode_value("1e3"), 1000.0)
        self.assertEqual(decode_value('"toto"'), "toto")
        self.assertEqual(decode_value("'toto'"), "toto")

    def test_collections(self):
        self.assertEqual(decode_value('["a","b"]'), ["a", "b"])
        self.assertEqual(decode_value("[]"), [])
        self.assertEqual(decode_value('[["bond","INSTANCE"]]'), [["bond", "INSTANCE"]])
        self.assertEqual(decode_value('{"k":"v","n":[1,true]}'), {"k": "v", "n": [1, True]})
        self.assertEqual(decode_value('{1:"toto",2:"tata"}'), {1: "toto", 2: "tata"})
        self.assertEqual(decode_value('{"a": [{"b":"c", "d":null}]}'),
                         {"a": [{"b": "c", "d": None}]})

    def test_not_a_literal_is_the_line(self):
        uuid = "9cc6cbec-52d8-49fe-b7f8-f3ddfe2a0ee7"
        for line in (uuid, "hrp2", '"unterminated', "[a, b]", "1 2", "{1:}", "True story"):
            self.assertEqual(decode_value(line), line)

    def test_string_escapes_json_and_python(self):
        self.assertEqual(decode_value(r'"a\"b\\c"'), 'a"b\\c')
        self.assertEqual(decode_value(r'"tab\there"'), "tab\there")
        self.assertEqual(decode_value(r'"\u0008\n\r\f"'), "\b\n\r\f")
        self.assertEqual(decode_value(r'"\x01\v\a\0"'), "\x01\v\a\0")
        self.assertEqual(decode_value(r'"\/"'), "/")
        self.assertEqual(decode_value(r'"it\'s"'), "it's")
        self.assertEqual(decode_value("'it\\'s'"), "it's")
        self.assertEqual(decode_value(r'"\U0001F600 \ud83d\ude00"'), "\U0001F600 \U0001F600")
        self.assertEqual(decode_value('"raw\ttab and \U0001F600"'), "raw\ttab and \U0001F600")
        self.assertEqual(decode_value(r'"unknown \q kept"'), "unknown \\q kept")
        self.assertEqual(decode_value(r'["a,b","c]d","e\"f"]'), ["a,b", "c]d", 'e"f'])

    def test_reply_lines(self):
        self.assertIsNone(decode_lines([""]))
        self.assertIsNone(decode_lines([]))
        self.assertEqual(decode_lines(['["x"]']), ["x"])
        self.assertEqual(decode_lines(['"line one', 'line two"']), "line one\nline two")


class EncodeTest(unittest.TestCase):

    def test_request(self):
        self.assertEqual(encode_request("hello", []), b"hello\n#end#\n")
        self.assertEqual(encode_request("add", [["a b c", 'd e "f, g"']]),
                         b'add\n["a b c","d e \\"f, g\\""]\n#end#\n')

    def test_strings_are_sent_as_they_are_but_on_one_line(self):
        self.assertEqual(encode_request("lookup", ["Bond, James Bond"]),
                         b"lookup\nBond, James Bond\n#end#\n")
        self.assertEqual(encode_request("lookup", ["a\nb\rc"]), b"lookup\na\\nb\\rc\n#end#\n")

    def test_elements(self):
        encoded = encode_request("m", [["it's", "back\\slash", "tab\t", "\x01", True, 2],
                                       {"k": "v"}, True, None, 1.5]).decode()
        self.assertEqual(encoded.split("\n")[1:6],
                         ['["it\\\'s","back\\\\slash","tab\\t","\\u0001",true,2]',
                          '{"k":"v"}', "true", "null", "1.5"])


class IdListTest(unittest.TestCase):

    def test_list_and_text(self):
        ids = IdList(["hrp2"])
        self.assertEqual(ids, ["hrp2"])
        self.assertIsInstance(ids, list)
        self.assertEqual("God save the queen! " + ids + " killed Bond!",
                         "God save the queen! hrp2 killed Bond!")
        self.assertEqual(IdList(["a", "b"]) + "!", "a, b!")
        self.assertEqual(IdList(["a"]) + ["b"], ["a", "b"])
        self.assertEqual(str(ids), "['hrp2']")


if __name__ == "__main__":
    unittest.main()
